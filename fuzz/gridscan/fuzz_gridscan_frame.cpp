// libFuzzer target: the CEDES frame codec ([GridScan manual §9.2]) on arbitrary bytes.
// Invariants: no crash; a frame inspect() accepts re-encodes to the same bytes when its
// sync and CRC were right; whatever decode_request/decode_response accept, inspect accepts
// with a good sync and CRC; decode_state never reads past its payload.
#include "gridscan/frame.h"
#include "gridscan/payload.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::gridscan;
  const std::span<const std::uint8_t> bytes(data, size);
  const auto raw = inspect(bytes);
  if (raw && raw.value().sync_ok && raw.value().crc_ok()) {
    const auto again = encode(raw.value().frame);
    if (!std::equal(again.begin(), again.end(), bytes.begin(), bytes.end())) std::abort();
  }
  const unsigned elements = size > 0 ? data[0] : 22U;
  for (const bool request : {true, false}) {
    const auto f = request ? decode_request(bytes) : decode_response(bytes, elements);
    if (!f) continue;
    if (!raw || !raw.value().sync_ok || !raw.value().crc_ok()) std::abort();
    if (!request) {
      const auto& p = f.value().payload;
      (void)decode_state(std::span<const std::uint8_t>(p.data(), p.size()));
    }
  }
  (void)decode_state(bytes);
  return 0;
}
