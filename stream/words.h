#pragma once
// The words of an option value such as `--mode blanking,cycle=30`: the RS-485 devices'
// mode specs (gridscan/, metron/, polaris/ mode_spec) split them the same way.

#include <string_view>
#include <vector>

namespace rs4sim::stream {

// `text` cut at every `sep`, in order; empty words kept ("a,,b" is a, "", b; "" is one empty
// word), so a caller names the empty word it refuses.
inline std::vector<std::string_view> split_words(std::string_view text, char sep = ',') {
  std::vector<std::string_view> words;
  while (true) {
    const auto at = text.find(sep);
    words.push_back(text.substr(0, at));
    if (at == std::string_view::npos) return words;
    text.remove_prefix(at + 1);
  }
}

}  // namespace rs4sim::stream
