// libFuzzer target: the parameter-set decoder (rs4/scanner/parameter_codec.h).
// Invariants: never crash; whatever decodes re-encodes to the same bytes (the encoding
// is deterministic and decode is its exact inverse); validation of any decoded set
// returns an issue or nothing, never crashes.
#include "rs4/scanner/parameter_codec.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::rs4::scanner;
  const std::span<const std::uint8_t> in(data, size);
  const auto decoded = decode(in);
  if (!decoded) return 0;
  const auto again = encode(decoded.value());
  if (again.size() != size || !std::equal(again.begin(), again.end(), in.begin())) std::abort();
  if (const auto issue = validate(decoded.value())) {
    if (issue->message().empty()) std::abort();
  }
  return 0;
}
