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
  // The device's own F_Dest_Add from the first byte: 0 (none), 4, ..., 504 (the default), ...
  DeviceProfile profile;
  profile.dest_add = size > 0 ? static_cast<std::uint16_t>(data[0] << 2) : std::uint16_t{504};
  const Validation from_bytes = validate(in, profile);
  const auto parsed = parse_f_parameters(in);
  if (!parsed) {
    if (from_bytes.fault != FParameterFault::kVersionMismatch) std::abort();
    return 0;
  }
  const auto again = encode_f_parameters_raw(parsed.value());
  if (std::memcmp(again.data(), data, kFParametersSize) != 0) std::abort();
  if (validate(parsed.value(), profile).fault != from_bytes.fault) std::abort();
  if (from_bytes.ok() && from_bytes.received_crc1 != from_bytes.computed_crc1) std::abort();
  return 0;
}
