// libFuzzer target: the parameter-set decoder (rs4/scanner/parameter_codec.h).
// Invariants: never crash; whatever decodes re-encodes to the same bytes; validation
// of a decoded set never crashes and a valid set survives a round trip unchanged.
#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <cstdlib>
#include <span>

#include "rs4/scanner/parameter_codec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::rs4::scanner;
  const std::span<const std::uint8_t> in(data, size);
  auto decoded = decode(in);
  if (!decoded) return 0;
  const auto again = encode(decoded.value());
  if (again.size() != size || !std::equal(again.begin(), again.end(), in.begin())) std::abort();
  if (!validate(decoded.value())) {
    auto checked = decode_and_validate(again);
    if (!checked || !(checked.value() == decoded.value())) std::abort();
  }
  (void)checksum(decoded.value());
  return 0;
}
