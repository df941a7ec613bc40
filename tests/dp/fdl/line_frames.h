#pragma once
// Test-side: every frame the streaming decoder finds on a recorded byte line, as it was on the
// wire, with its offset. The line is fed one byte at a time, so a frame ends at the byte just
// fed: its bytes are the line's bytes before that point. Telegrams must re-encode to exactly
// those bytes (`mismatches` counts those that do not); frames whose framing is right but whose
// content DP refuses come from DecoderSink::on_refused_frame.

#include "dp/fdl/decoder.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace rs4sim::dp::fdl::testing {

struct LineFrame {
  std::size_t offset = 0;  // of the start delimiter in the line
  std::span<const std::uint8_t> bytes;
  std::error_code refused;  // set for a frame DP refuses (on_refused_frame)
};

class LineFrames final : public DecoderSink {
 public:
  explicit LineFrames(std::span<const std::uint8_t> line) : line_(line) {
    for (pos_ = 1; pos_ <= line_.size(); ++pos_) decoder_.feed(line_.subspan(pos_ - 1, 1), *this);
    pos_ = line_.size();
    decoder_.idle(*this);
  }

  void on_telegram(const Telegram& t) override {
    const auto frame = add(encoded_size(t), {});
    encoded_.clear();
    encode(t, encoded_);
    if (!std::equal(encoded_.begin(), encoded_.end(), frame.begin(), frame.end())) ++mismatches;
  }
  void on_refused_frame(std::span<const std::uint8_t> frame, std::error_code e) override {
    const auto on_line = add(frame.size(), e);
    if (!std::equal(frame.begin(), frame.end(), on_line.begin(), on_line.end())) ++mismatches;
  }

  // Frames by start delimiter (0x10 SD1, 0x68 SD2, 0xA2 SD3, 0xDC token, 0xE5 SC).
  [[nodiscard]] std::size_t count(std::uint8_t sd) const {
    std::size_t n = 0;
    for (const auto& f : frames) n += f.bytes[0] == sd ? 1U : 0U;
    return n;
  }
  [[nodiscard]] const DecoderStats& stats() const { return decoder_.stats(); }

  std::vector<LineFrame> frames;
  std::size_t mismatches = 0;

 private:
  std::span<const std::uint8_t> add(std::size_t size, std::error_code refused) {
    const auto bytes = line_.subspan(pos_ - size, size);
    frames.push_back({pos_ - size, bytes, refused});
    return bytes;
  }

  std::span<const std::uint8_t> line_;
  std::size_t pos_ = 0;
  Decoder decoder_;
  std::vector<std::uint8_t> encoded_;
};

}  // namespace rs4sim::dp::fdl::testing
