#include "polaris/data_modes.h"

namespace rs4sim::polaris {

namespace {

constexpr std::size_t kBitsPerWord = 16;

std::size_t fl_objects(DataMode m) noexcept {
  switch (m) {
    case DataMode::kFl1: return 0;
    case DataMode::kFl4: return 4;
    case DataMode::kFl10: return 10;
    case DataMode::k485Mb: break;
  }
  return 0;
}

// interrupted, in transmitted numbering: index i is beam i+1.
std::vector<bool> transmitted(const Options& o, std::span<const std::uint8_t> interrupted) {
  std::vector<bool> out(o.beams, false);
  for (std::size_t i = 0; i < out.size() && i < interrupted.size(); ++i) {
    const std::size_t at = o.direction == ScanDirection::kDirect ? i : out.size() - 1 - i;
    out[at] = interrupted[i] != 0;
  }
  return out;
}

std::vector<std::uint16_t> bit_words(const Options& o, const std::vector<bool>& beams) {
  std::vector<std::uint16_t> words(block_words(o), 0xFFFF);
  for (std::size_t i = 0; i < beams.size(); ++i) {
    if (!beams[i]) continue;
    const std::size_t bit = i % kBitsPerWord;
    const std::size_t shift = o.bit_order == BitOrder::kLsbFirst ? bit : kBitsPerWord - 1 - bit;
    std::uint16_t& w = words[i / kBitsPerWord];
    w = static_cast<std::uint16_t>(w & ~(1U << shift));
  }
  return words;
}

}  // namespace

std::vector<Object> find_objects(const Options& o, std::span<const std::uint8_t> interrupted) {
  const std::vector<bool> beams = transmitted(o, interrupted);
  std::vector<Object> objects;
  for (std::size_t i = 0; i < beams.size(); ++i) {
    if (!beams[i]) continue;
    const auto number = static_cast<std::uint16_t>(i + 1);
    if (i > 0 && beams[i - 1]) {
      objects.back().last = number;
    } else {
      objects.push_back(Object{number, number});
    }
  }
  return objects;
}

std::vector<std::uint16_t> data_words(const Options& o, std::span<const std::uint8_t> interrupted) {
  if (o.mode == DataMode::k485Mb) return bit_words(o, transmitted(o, interrupted));
  const std::vector<Object> objects = find_objects(o, interrupted);
  std::vector<std::uint16_t> words;
  words.reserve(block_words(o));
  const std::size_t pairs = fl_objects(o.mode);
  for (std::size_t k = 0; k < pairs; ++k) {
    const Object obj = k < objects.size() ? objects[k] : Object{};
    words.push_back(obj.first);
    words.push_back(obj.last);
  }
  words.push_back(objects.empty() ? std::uint16_t{0} : objects.front().first);
  words.push_back(objects.empty() ? std::uint16_t{0} : objects.back().last);
  return words;
}

std::size_t block_words(const Options& o) noexcept {
  if (o.mode == DataMode::k485Mb) return (o.beams + kBitsPerWord - 1) / kBitsPerWord;
  return 2 * fl_objects(o.mode) + 2;
}

}  // namespace rs4sim::polaris
