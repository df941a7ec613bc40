#pragma once
// PROFIBUS FDL telegrams (layer 2), [IEC 61158-4-3].
//
// A `Telegram` is the decoded, validated content of one frame; `encode` turns it back
// into wire bytes (start delimiter … end delimiter). The streaming decoder that cuts a
// byte stream into telegrams lives in decoder.h.

#include <boost/container/static_vector.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::dp::fdl {

inline constexpr std::uint8_t kBroadcastAddress = 127;
inline constexpr std::size_t kMaxDataUnit = 246;      // DU incl. DSAP/SSAP bytes (LE 249 - 3)
inline constexpr std::size_t kMaxTelegramSize = 255;  // SD2 with LE 249

enum class FrameType : std::uint8_t { kSd1, kSd2, kSd3, kToken, kShortAck };

// Start delimiters and the end delimiter ([IEC 61158-4-3 frame formats]). Declared after FrameType
// so that its scoped enumerators of the same names do not trigger -Wshadow.
inline constexpr std::uint8_t kSd1 = 0x10;  // fixed length, no data unit
inline constexpr std::uint8_t kSd2 = 0x68;  // variable length, LE 4..249
inline constexpr std::uint8_t kSd3 = 0xA2;  // fixed length, 8 DU bytes
inline constexpr std::uint8_t kSd4 = 0xDC;  // token
inline constexpr std::uint8_t kSc = 0xE5;   // short acknowledgement
inline constexpr std::uint8_t kEd = 0x16;

// Request function codes, FC bits 3..0 when bit 6 = 1 ([IEC 61158-4-3 frame control]).
enum class RequestFunction : std::uint8_t {
  kTimeEvent = 0x0,
  kSdaLow = 0x3,
  kSdnLow = 0x4,
  kSdaHigh = 0x5,
  kSdnHigh = 0x6,
  kMsrd = 0x7,
  kFdlStatus = 0x9,
  kSrdLow = 0xC,
  kSrdHigh = 0xD,
  kIdent = 0xE,
  kLsapStatus = 0xF,
};

// Response status, FC bits 3..0 when bit 6 = 0 ([IEC 61158-4-3 frame control]).
enum class ResponseStatus : std::uint8_t {
  kOk = 0x0,
  kUserError = 0x1,
  kNoResource = 0x2,
  kSapNotEnabled = 0x3,  // RS
  kDataLow = 0x8,        // DL: normal DP reply
  kNoData = 0x9,         // NR
  kDataHigh = 0xA,       // DH: diagnosis pending
  kNotReceivedDataLow = 0xC,
  kNotReceivedDataHigh = 0xD,
};

// Station type of a responder, FC bits 5..4 when bit 6 = 0.
enum class StationType : std::uint8_t {
  kSlave = 0,
  kMasterNotReady = 1,
  kMasterReady = 2,
  kMasterInRing = 3,
};

// The frame control byte, split into its fields. `raw` is what travels on the wire.
struct FrameControl {
  std::uint8_t raw = 0;

  [[nodiscard]] constexpr bool is_request() const { return (raw & 0x40) != 0; }
  [[nodiscard]] constexpr bool fcb() const { return (raw & 0x20) != 0; }
  [[nodiscard]] constexpr bool fcv() const { return (raw & 0x10) != 0; }
  [[nodiscard]] constexpr std::uint8_t code() const { return raw & 0x0F; }
  [[nodiscard]] constexpr RequestFunction function() const {
    return static_cast<RequestFunction>(code());
  }
  [[nodiscard]] constexpr ResponseStatus status() const {
    return static_cast<ResponseStatus>(code());
  }
  [[nodiscard]] constexpr StationType station_type() const {
    return static_cast<StationType>((raw >> 4) & 0x03);
  }

  static constexpr FrameControl request(RequestFunction f, bool fcb, bool fcv) {
    return {static_cast<std::uint8_t>(0x40 | (fcb ? 0x20 : 0) | (fcv ? 0x10 : 0) |
                                      static_cast<std::uint8_t>(f))};
  }
  static constexpr FrameControl response(ResponseStatus s, StationType t = StationType::kSlave) {
    return {static_cast<std::uint8_t>((static_cast<std::uint8_t>(t) << 4) |
                                      static_cast<std::uint8_t>(s))};
  }
  friend constexpr bool operator==(FrameControl, FrameControl) = default;
};

// Data unit storage: no heap allocation on the cyclic path.
using DataUnit = boost::container::static_vector<std::uint8_t, kMaxDataUnit>;

// One FDL telegram. Addresses are stored without the extension bit (0..127); the
// extension bit on the wire is derived from dsap/ssap being present
// ([IEC 61158-4-3 addresses, SAPs]). For DP, dsap and ssap are either both present (a DP service
// SAP) or both absent (default SAP = Data_Exchange). `data` is the DU *after* the DSAP/SSAP bytes.
struct Telegram {
  FrameType type = FrameType::kSd2;
  std::uint8_t da = 0;  // destination address (token: DA)
  std::uint8_t sa = 0;  // source address (token: SA)
  FrameControl fc{};    // absent for token and short ack
  std::optional<std::uint8_t> dsap;
  std::optional<std::uint8_t> ssap;
  DataUnit data;

  friend bool operator==(const Telegram&, const Telegram&) = default;
};

// Builders for the common shapes. `make_data_telegram` picks SD1 when the DU (including
// SAP bytes) is empty and SD2 otherwise (SD2 is always legal, [IEC 61158-4-3 frame formats]). It
// throws std::invalid_argument if `data` is longer than kMaxDataUnit.
Telegram make_short_ack();
Telegram make_token(std::uint8_t da, std::uint8_t sa);
Telegram make_data_telegram(std::uint8_t da, std::uint8_t sa, FrameControl fc,
                            std::optional<std::uint8_t> dsap, std::optional<std::uint8_t> ssap,
                            std::span<const std::uint8_t> data);

// FCS: arithmetic sum mod 256 of DA..last DU byte, extension bytes included ([IEC 61158-4-3 FCS]).
// Inline and table-free, 8 bytes per step: each 64-bit word is split into four 16-bit lane
// sums kept mod 256 (no carry crosses a lane), a loop the compiler may vectorise. On a
// little-endian host the last 1..7 bytes are one overlapping word whose bytes already
// counted are masked off, so a 9-byte Data_Exchange header+DU costs two words, no loop tail.
inline std::uint8_t frame_check_sequence(std::span<const std::uint8_t> da_to_du) {
  constexpr std::uint64_t kEven = 0x00FF00FF00FF00FFULL;
  const std::uint8_t* p = da_to_du.data();
  const std::size_t size = da_to_du.size();
  const auto word_at = [p](std::size_t i) {
    std::uint64_t w = 0;
    std::memcpy(&w, p + i, 8);
    return w;
  };
  const auto lane_sums = [](std::uint64_t w) { return (w & kEven) + ((w >> 8) & kEven); };
  std::uint64_t lanes = 0;
  std::size_t i = 0;
  for (; i + 8 <= size; i += 8) lanes = (lanes & kEven) + lane_sums(word_at(i));
  std::uint8_t tail = 0;
  if constexpr (std::endian::native == std::endian::little) {
    if (i != size && size >= 8) {
      const std::size_t fresh = size - i;  // 1..7 bytes at the top of the last word
      lanes = (lanes & kEven) + lane_sums(word_at(size - 8) & (~0ULL << (64 - 8 * fresh)));
      i = size;
    }
  }
  for (; i != size; ++i) tail = static_cast<std::uint8_t>(tail + p[i]);
  lanes &= kEven;
  return static_cast<std::uint8_t>(((lanes * 0x0001000100010001ULL) >> 48) + tail);
}

// Appends the wire bytes of `t` to `out`; returns the number of bytes written.
// Precondition (checked, throws std::invalid_argument): DU fits (≤ 246 incl. SAP bytes),
// addresses ≤ 127, SD3 has exactly 8 DU bytes incl. SAP bytes, SD1 has none.
std::size_t encode(const Telegram& t, std::vector<std::uint8_t>& out);

// Allocation-free form for the hot path: writes into `out` (needs ≥ encoded_size(t) bytes,
// kMaxTelegramSize always suffices); returns the number of bytes written. Same checks.
std::size_t encode(const Telegram& t, std::span<std::uint8_t> out);

// Size on the wire of `t` (same rules as encode), for wire-time computations.
std::size_t encoded_size(const Telegram& t);

}  // namespace rs4sim::dp::fdl
