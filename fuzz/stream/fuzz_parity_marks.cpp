// Drives stream::ParityMarks with the input cut into chunks at positions the input names and
// checks it against a reference model of [termios(3) PARMRK] decoding on the whole input:
// same good bytes, same damaged characters, in the same order, whatever the cuts.
#include "stream/parity_marks.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <utility>
#include <vector>

namespace {

// (byte, damaged) pairs in line order.
using Events = std::vector<std::pair<std::uint8_t, bool>>;

Events reference(std::span<const std::uint8_t> in, std::size_t& pending) {
  Events out;
  std::size_t i = 0;
  for (; i < in.size(); ++i) {
    if (in[i] != 0xFF) {
      out.emplace_back(in[i], false);
    } else if (i + 1 >= in.size()) {
      pending = 1;
      return out;
    } else if (in[i + 1] == 0xFF) {
      out.emplace_back(0xFF, false), ++i;
    } else if (in[i + 1] == 0x00) {
      if (i + 2 >= in.size()) {
        pending = 2;
        return out;
      }
      out.emplace_back(in[i + 2], true), i += 2;
    } else {
      out.emplace_back(0xFF, false), out.emplace_back(in[i + 1], false), ++i;
    }
  }
  pending = 0;
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t step = data[0] % 7U + 1U;  // chunk length
  const auto input = std::span(data + 1, size - 1);
  rs4sim::stream::ParityMarks marks;
  Events got;
  for (std::size_t at = 0; at < input.size(); at += step) {
    marks.feed(
        input.subspan(at, std::min(step, input.size() - at)),
        [&](std::span<const std::uint8_t> b) {
          if (b.empty()) std::abort();  // a run is never empty
          for (const auto c : b) got.emplace_back(c, false);
        },
        [&](std::uint8_t c) { got.emplace_back(c, true); });
  }
  std::size_t pending = 0;
  if (got != reference(input, pending) || marks.pending() != pending) std::abort();
  return 0;
}
