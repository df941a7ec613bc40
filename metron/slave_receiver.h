#pragma once
// Cuts the host's bytes into slave-mode messages [METRON manual "No node", "With node"]:
//   Frame start | [Address] | Length | Command | Data (0..5) | Checksum
// Length counts Command + Data and is at most 6; the checksum covers Command + Data only.
// The receiver only delimits and checks; what a message means is slave_handler.h's.
//
// Where the manual is silent (DECISION, [docs/metron.md#receiving]):
// - bytes before a frame start are line noise: dropped and counted;
// - a message whose bytes stop for receive_timeout is truncated: dropped without a reply;
// - a Length above 6 ends the message after the Length byte (its end cannot be known; the
//   answer is E1); the bytes that follow it without a pause of `resync_gap` are dropped;
// - a Length of 0 (no command) is read with its checksum byte and answered E2.

#include "metron/checksum.h"
#include "stream/clock.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>

namespace rs4sim::metron {

struct SlaveMessage {
  std::optional<std::uint8_t> address;  // node mode only
  std::uint8_t length = 0;              // the Length field as received
  std::array<std::uint8_t, 6> body{};   // Command, Data...; valid up to body_size()
  std::uint8_t checksum = 0;            // as received
  bool length_too_long = false;         // Length > 6: nothing after it was read
  bool checksum_ok = false;
  bool parity_error = false;  // a byte of it failed the parity check
  stream::TimePoint first_byte{};
  std::size_t wire_bytes = 0;  // n_byte of Equation 3

  [[nodiscard]] std::size_t body_size() const { return length_too_long ? 0 : length; }
  [[nodiscard]] std::uint8_t command() const { return body_size() > 0 ? body[0] : 0; }
  [[nodiscard]] std::span<const std::uint8_t> data() const {
    return body_size() > 1 ? std::span<const std::uint8_t>(body).subspan(1, body_size() - 1)
                           : std::span<const std::uint8_t>{};
  }
};

struct ReceiverStats {
  std::uint64_t messages = 0;
  std::uint64_t noise_bytes = 0;
  std::uint64_t truncated = 0;
  std::uint64_t too_long = 0;
  std::uint64_t resync_bytes = 0;  // dropped after a too-long Length
};

struct ReceiverConfig {
  bool node_mode = false;
  std::uint8_t frame_start = 0x02;
  ChecksumReading checksum_reading = ChecksumReading::kModulo256;
  stream::Duration receive_timeout{};
  stream::Duration resync_gap{};
};

class SlaveReceiver {
 public:
  explicit SlaveReceiver(const ReceiverConfig& config) : config_(config) {}

  void feed(std::span<const std::uint8_t> bytes, stream::TimePoint now);
  // The byte fed last failed its parity check: its message is rejected.
  void mark_parity_error();
  // The next complete message, oldest first; drops a partial one older than the timeout.
  std::optional<SlaveMessage> poll(stream::TimePoint now);
  // When a partial message times out; nullopt when none is pending.
  [[nodiscard]] std::optional<stream::TimePoint> deadline() const;
  void reset();

  [[nodiscard]] const ReceiverStats& stats() const { return stats_; }

 private:
  enum class Field : std::uint8_t { kStart, kAddress, kLength, kBody, kChecksum };
  void take(std::uint8_t byte, stream::TimePoint now);
  void complete();
  void expire(stream::TimePoint now);

  ReceiverConfig config_;
  Field field_ = Field::kStart;
  SlaveMessage partial_;
  std::size_t body_read_ = 0;
  stream::TimePoint last_byte_{};
  std::optional<stream::TimePoint> resync_until_;
  bool last_byte_completed_ = false;
  std::deque<SlaveMessage> ready_;
  ReceiverStats stats_;
};

}  // namespace rs4sim::metron
