#pragma once
// The CEDES frame ([GridScan manual §9.2]):
//
//   offset 0..3   sync pattern 43 45 44 45 ("CEDE", 0x45444543 LE); not under the CRC
//   offset 4      SeqCnt, 8 bit ([GridScan manual §9.2.2])
//   offset 5      ID: bits 0..6 command, bit 7 direction (1 = curtain → controller)
//   offset 6..    payload, 0..10 bytes; requests never carry one ([GridScan manual §9.2.4])
//   last 4        CRC-32/MPEG-2 over SeqCnt, ID and payload, least significant byte first
//
// Requests are therefore 10 bytes, responses 10..20. The manual's sync value "0x454444543"
// has nine digits; the bytes of its every example are 43 45 44 45 (docs/gridscan.md).

#include "gridscan/errors.h"

#include <boost/container/static_vector.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::gridscan {

inline constexpr std::array<std::uint8_t, 4> kSyncBytes{0x43, 0x45, 0x44, 0x45};
inline constexpr std::uint32_t kSync = 0x45444543;  // kSyncBytes read little-endian
inline constexpr std::size_t kHeaderSize = 6;       // sync, SeqCnt, ID
inline constexpr std::size_t kCrcSize = 4;
inline constexpr std::size_t kMaxPayload = 10;
inline constexpr std::size_t kMinFrame = kHeaderSize + kCrcSize;   // 10: every request
inline constexpr std::size_t kMaxFrame = kMinFrame + kMaxPayload;  // 20
inline constexpr std::uint8_t kDirectionBit = 0x80;                // ID bit 7
inline constexpr std::uint8_t kIdMask = 0x7F;

// The commands of [GridScan manual §9.2.3], by the manual's names.
enum class CommandId : std::uint8_t {
  kModeSetPolling = 0x10,
  kModeSetFullStreaming = 0x11,
  kModeSetReducedStreaming = 0x12,
  kModeSetStandBy = 0x13,
  kModeGetCurrent = 0x14,
  kInfoGetVersion = 0x20,
  kInfoGetProductInformation = 0x21,
  kInfoGetCountOfElements = 0x22,
  kInfoCommunicationTest = 0x23,
  kInfoGetAlignmentValue = 0x24,
  kInfoRequestAlignmentMode = 0x25,
  kDataReducedState = 0x30,
  kDataFullState = 0x31,
  kSafetyTestInput = 0x40,
  kConfigAllowChange = 0x50,
  kConfigSetStatic = 0x51,
  kConfigSetBlanking = 0x52,
  kConfigGetCurrent = 0x53,
};

// The command named by bits 0..6 of an ID byte, if the manual lists it.
[[nodiscard]] std::optional<CommandId> command_of(std::uint8_t id_byte) noexcept;
[[nodiscard]] constexpr std::uint8_t request_id(CommandId c) noexcept {
  return static_cast<std::uint8_t>(c);
}
[[nodiscard]] constexpr std::uint8_t response_id(CommandId c) noexcept {
  return static_cast<std::uint8_t>(static_cast<std::uint8_t>(c) | kDirectionBit);
}

using Payload = boost::container::static_vector<std::uint8_t, kMaxPayload>;

struct Frame {
  std::uint8_t seq = 0;
  std::uint8_t id = 0;  // the whole ID byte, direction bit included
  Payload payload;

  friend bool operator==(const Frame&, const Frame&) = default;
};

// The whole frame on the wire: sync, SeqCnt, ID, payload, CRC (LE).
[[nodiscard]] std::vector<std::uint8_t> encode(const Frame& f);

// A frame split into its fields without judging them: what the curtain needs to answer
// the communication test, which reports a bad sync or CRC instead of dropping the frame
// ([GridScan manual §10.3]). Fails only when the length cannot hold the fields.
struct RawFrame {
  Frame frame;
  std::uint32_t crc_received = 0;
  std::uint32_t crc_computed = 0;
  bool sync_ok = false;
  [[nodiscard]] bool crc_ok() const noexcept { return crc_received == crc_computed; }
};
[[nodiscard]] Result<RawFrame> inspect(std::span<const std::uint8_t> bytes);

// Strict decoders: a controller → curtain request (10 bytes, bit 7 clear, known ID) and a
// curtain → controller response (bit 7 set, known ID, payload length of that ID for
// `elements`; a length check needs the element count only for Full state).
[[nodiscard]] Result<Frame> decode_request(std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<Frame> decode_response(std::span<const std::uint8_t> bytes, unsigned elements);

// Response payload length of a command ([GridScan manual §9.2.4]); Full state: 2 + ⌈N/8⌉.
[[nodiscard]] std::size_t response_payload_size(CommandId c, unsigned elements) noexcept;

}  // namespace rs4sim::gridscan
