#pragma once
// The RS4's own RS232 framing behind the optical PC adapter ([roboticslibrary/rl LeuzeRs4.cpp];
// the manual only says the block header replaces it):
//   00 00 | stuffed body (CMD, options, [password], data) | CHK | 00 00 00
// Zero-stuffing: after two consecutive 0x00 inside the body a 0xFF is inserted (the
// receiver drops it and restarts its zero count), so three zeros mark the end.
// CHK: XOR of every transmitted body byte (stuffed 0xFF included); 0x00 is sent as 0xFF.
// CMD is never 0x00 or 0xFF.

#include "rs4/protocol/errors.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::rs4::protocol {

inline constexpr std::uint8_t kStuffByte = 0xFF;

// Appends one frame for `body` to `out`. kEmptyFrame, kBadCommandByte.
std::error_code frame_rs232(std::span<const std::uint8_t> body, std::vector<std::uint8_t>& out);
Result<std::vector<std::uint8_t>> frame_rs232(std::span<const std::uint8_t> body);

struct DeframerCounters {
  std::uint64_t frames = 0;             // good frames delivered
  std::uint64_t garbage_bytes = 0;      // bytes outside any frame that are not zeros
  std::uint64_t check_errors = 0;       // kBadCheck
  std::uint64_t stuffing_errors = 0;    // kStuffingViolation
  std::uint64_t short_frames = 0;       // kFrameTooShort
  std::uint64_t long_frames = 0;        // kFrameTooLong
  std::uint64_t bad_command_bytes = 0;  // kBadCommandByte (00 00 FF outside a frame)
};

// Streaming receiver: feed it chunks of any size; it reports each complete frame's body
// (unstuffed, without CHK) or a typed error, and resynchronises on the next `00 00 x`
// with x ∉ {00, FF}. Memory is bounded by max_body.
class Rs232Deframer {
 public:
  static constexpr std::size_t kDefaultMaxBody = 4096;
  explicit Rs232Deframer(std::size_t max_body = kDefaultMaxBody) : max_body_(max_body) {}

  using Event = Result<std::vector<std::uint8_t>>;
  // Appends one event per finished frame or error to `events`.
  void feed(std::span<const std::uint8_t> bytes, std::vector<Event>& events);
  std::vector<Event> feed(std::span<const std::uint8_t> bytes);

  const DeframerCounters& counters() const noexcept { return counters_; }
  bool in_frame() const noexcept { return in_frame_; }

 private:
  void idle_byte(std::uint8_t byte);
  void frame_byte(std::uint8_t byte, std::vector<Event>& events);
  void start_frame(std::uint8_t cmd);
  void finish_frame(std::vector<Event>& events);
  void fail(ProtocolError error, std::vector<Event>& events);

  std::size_t max_body_;
  bool in_frame_ = false;
  unsigned zeros_ = 0;    // consecutive zeros seen (outside: since the last non-zero)
  std::uint8_t xor_ = 0;  // XOR of every transmitted byte of the current frame
  std::vector<std::uint8_t> body_;
  DeframerCounters counters_;
};

}  // namespace rs4sim::rs4::protocol
