#include "gridscan/mode_spec.h"

#include "stream/words.h"

#include <charconv>

namespace rs4sim::gridscan {

std::string apply_mode_spec(std::string_view spec, Options& o) {
  bool first = true;
  for (const std::string_view word : stream::split_words(spec, ',')) {
    if (first) {
      if (word == "blanking") o.configuration = Configuration::kBlanking;
      else if (word == "static") o.configuration = Configuration::kStatic;
      else return "'" + std::string(word) + "': use blanking or static";
      first = false;
    } else if (word.starts_with("cycle=")) {
      const auto v = word.substr(6);
      unsigned ms = 0;
      const auto r = std::from_chars(v.data(), v.data() + v.size(), ms);
      if (v.empty() || r.ec != std::errc{} || r.ptr != v.data() + v.size()) {
        return "'" + std::string(word) + "': cycle= takes milliseconds, e.g. cycle=30";
      }
      if (auto why = check_cycle(o.elements, std::chrono::milliseconds(ms)); !why.empty()) {
        return "'" + std::string(word) + "': " + why;
      }
      o.cycle = std::chrono::milliseconds(ms);
    } else {
      return "'" + std::string(word) + "' is none of cycle= (after blanking or static)";
    }
  }
  return {};
}

}  // namespace rs4sim::gridscan
