// libFuzzer target: decode_state() (rs4/device/rs4_state.h) on any bytes. Invariants: no
// crash; what decodes encodes back to the same bytes (the format has one encoding per state).
#include "rs4/device/rs4_state.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  const auto state = rs4sim::rs4::device::decode_state(bytes);
  if (state) {
    const auto again = rs4sim::rs4::device::encode_state(state.value());
    if (again.size() != size || !std::equal(again.begin(), again.end(), bytes.begin())) {
      std::abort();
    }
  }
  return 0;
}
