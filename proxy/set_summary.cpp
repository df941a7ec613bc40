// Summary texts for the archive.
#include "proxy/set_summary.h"

#include "rs4/scanner/parameter_codec.h"

#include <algorithm>

namespace rs4sim::proxy {

std::string set_summary(std::span<const std::uint8_t> blob) {
  const auto set = rs4::scanner::decode(blob);
  if (!set) return "undecodable set (" + set.error().message() + ")";
  const auto& s = set.value();
  int pairs = 0;
  for (const auto& pair : s.pairs) {
    const bool used = std::any_of(pair.protective_mm.begin(), pair.protective_mm.end(),
                                  [](auto mm) { return mm != 0; });
    if (used) ++pairs;
  }
  return "start pair " + std::to_string(s.start_pair) + ", response steps " +
         std::to_string(s.response_steps) + ", restart mode " +
         std::to_string(static_cast<int>(s.restart_mode)) + ", " + std::to_string(pairs) +
         " field pairs with a protective field";
}

}  // namespace rs4sim::proxy
