#pragma once
// Response payloads of the CEDES protocol ([GridScan manual §9.2.4]). Bit k of a payload
// is bit k mod 8 of payload byte k div 8 (least significant byte first); reserved bits are
// sent as 0.

#include "gridscan/errors.h"
#include "gridscan/frame.h"

#include <cstdint>
#include <span>
#include <string_view>

namespace rs4sim::gridscan {

// Mode: Get current, bits 0..1 ([GridScan manual §9.2.4]).
enum class CommMode : std::uint8_t {
  kPolling = 0,
  kFullStreaming = 1,
  kReducedStreaming = 2,
  kStandBy = 3,
};

// Config: Get current ([GridScan manual §9.2.4]); the operating mode of the curtain.
enum class Configuration : std::uint8_t { kStatic = 0x55, kBlanking = 0xAA };

// The API's, the CLI's and the event stream's words: "polling", "full-streaming",
// "reduced-streaming", "stand-by"; "static", "blanking".
[[nodiscard]] std::string_view to_token(CommMode m) noexcept;
[[nodiscard]] std::string_view to_token(Configuration c) noexcept;

// Config: Allow change, bits 0..1.
enum class AllowChange : std::uint8_t { kAllowed = 0, kNotInStandBy = 1, kWindowOver = 2 };

// Config: Set static / Set blanking, bits 0..2; sent only when the change failed.
enum class SetConfigResult : std::uint8_t {
  kSetButNoReset = 0,
  kNotSet = 1,
  kNotRead = 2,     // Config: Get current (0x53) was not sent first
  kNotAllowed = 3,  // Config: Allow change (0x50) was not sent first
  kNotInStandBy = 4,
  kWindowOver = 5,  // more than 120 s after power-up
};

// Info: Communication test bits ([GridScan manual §9.2.4]).
inline constexpr std::uint8_t kCommTestCrcWrong = 0x01;
inline constexpr std::uint8_t kCommTestSeqCntWrong = 0x02;
inline constexpr std::uint8_t kCommTestSyncWrong = 0x04;

// The door position value of static mode: "no information" ([GridScan manual §9.2.4]).
inline constexpr std::uint8_t kDoorPositionStatic = 255;
inline constexpr unsigned kMinElements = 12;
inline constexpr unsigned kMaxElements = 60;

// Data: Reduced / Full state. Bit 0 of `elements` is element 1 (the bottom one).
struct StateReport {
  std::uint8_t door_position = 0;  // bits 0..7
  bool interrupted = false;        // bit 8: an element below the door edge is interrupted
  bool internal_failure = false;   // bit 9
  std::uint8_t maintenance = 0;    // bits 14..15: 0 clean .. 3 heavy soiling
  std::uint64_t elements = 0;      // bits 16..75 (Full state only)

  friend bool operator==(const StateReport&, const StateReport&) = default;
};

[[nodiscard]] Payload encode_reduced_state(const StateReport& s);
[[nodiscard]] Payload encode_full_state(const StateReport& s, unsigned element_count);
// Reads a Reduced (2 bytes) or Full (2 + ⌈N/8⌉ bytes) state payload; reserved bits ignored.
[[nodiscard]] Result<StateReport> decode_state(std::span<const std::uint8_t> payload);

// Info: Get version: bytes 0..4 SW "xx.yy", bytes 5..9 HW "xx.yy", first character at the
// lowest byte. Both strings must be 5 characters.
[[nodiscard]] Result<Payload> encode_version(std::string_view sw, std::string_view hw);
// Info: Get product information: bytes 0..5 the part number (6 ASCII digits), 6..8
// reserved, 9 the element count.
[[nodiscard]] Result<Payload> encode_product_information(std::string_view part_number,
                                                         unsigned element_count);
[[nodiscard]] Payload encode_u8(std::uint8_t v);
[[nodiscard]] Payload encode_u16_le(std::uint16_t v);

}  // namespace rs4sim::gridscan
