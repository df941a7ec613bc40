// libFuzzer target: the F-parameter block parser and the device-side validation
// (profisafe/f_parameters.h). Invariants: never crash; a parsed block re-encodes to the
// same bytes; validation of bytes equals validation of the parsed struct.
#include "profisafe/f_parameters.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::profisafe;
  const std::span<const std::uint8_t> in(data, size);
  const unsigned address = size > 0 ? data[0] : 4u;
  const DeviceProfile profile = DeviceProfile::rs4(address);
  const Validation from_bytes = validate(in, profile);
  const auto parsed = parse_f_parameters(in);
  if (!parsed) {
    if (from_bytes.diagnosis != FDiagnosis::kWrongBlockIdOrParVersion) std::abort();
    return 0;
  }
  const auto again = encode_f_parameters_raw(parsed.value());
  if (std::memcmp(again.data(), data, kFParametersSize) != 0) std::abort();
  if (validate(parsed.value(), profile).diagnosis != from_bytes.diagnosis) std::abort();
  if (from_bytes.ok() && status_pdu(from_bytes.diagnosis)[4] != 0) std::abort();
  return 0;
}
