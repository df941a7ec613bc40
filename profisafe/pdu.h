#pragma once
// The cyclic safety PDU ([PROFIsafe V1.30 safety PDU] [IEC 61784-3-3 CRC2]).
//
//   V1 (2-byte CRC2):  F-data[N] | status/control | consecutive number | CRC2 hi | CRC2 lo
//   V2 (3-byte CRC2):  F-data[N] | status/control | CRC2 (3 bytes, high first)
//   V2 (4-byte CRC2):  F-data[N] | status/control | CRC2 (4 bytes, high first; F_CRC_Length 2)
//
// V1 with N = 1 is five bytes each way. CRC2 runs over F-data, the
// status/control byte and the consecutive number (V1: only when F_Check_SeqNr = 1, or as
// the Crc2Variant says; V2: always, as a 4-byte virtual number that is not sent).
//
// V1 CRC2 is UNCERTAIN (no public V1 capture): Crc2Variant names every choice; the default is the
// candidate rule, by analogy with the VERIFIED V2 rule: CRC-16 0x4EAB, preset CRC1, input
// [consecutive number if F_Check_SeqNr] + F-data + status/control, fed in reverse.

#include "profisafe/errors.h"
#include "profisafe/f_parameters.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::profisafe {

enum class ProtocolVersion : std::uint8_t { kV1 = 0, kV2 = 1 };

// Largest F-data size this implementation supports (the short PDU format of both versions).
inline constexpr std::size_t kMaxDataSize = 12;
inline constexpr std::size_t kMaxPduSize = kMaxDataSize + 5;  // V2 with a 4-byte CRC2

// Status byte, device → host ([PROFIsafe V1.30 safety PDU]). V1 defines CE_CRC, WD_timeout,
// FV_activated only.
namespace status_bit {
inline constexpr std::uint8_t kIparOk = 0x01;       // V2
inline constexpr std::uint8_t kDeviceFault = 0x02;  // V2
inline constexpr std::uint8_t kCeCrc = 0x04;        // CE_CRC: CRC (communication) error detected
inline constexpr std::uint8_t kWdTimeout = 0x08;    // WD_timeout: watchdog expired
inline constexpr std::uint8_t kFvActivated = 0x10;  // FV_activated: fail-safe values active
inline constexpr std::uint8_t kToggleD = 0x20;      // V2
inline constexpr std::uint8_t kConsNrR = 0x40;      // V2 cons_nr_R
}  // namespace status_bit

// Control byte, host → device ([PROFIsafe V1.30 safety PDU]). V1 defines activate_FV only; unknown
// bits are ignored.
namespace control_bit {
inline constexpr std::uint8_t kIparEn = 0x01;      // V2
inline constexpr std::uint8_t kOaReq = 0x02;       // V2
inline constexpr std::uint8_t kRConsNr = 0x04;     // V2 R_cons_nr
inline constexpr std::uint8_t kActivateFv = 0x10;  // activate_FV
inline constexpr std::uint8_t kToggleH = 0x20;     // V2
}  // namespace control_bit

// The V1 CRC2 rule as named choices ([IEC 61784-3-3 CRC2] [docs/decisions.md#profisafe-v1-crc2],
// UNCERTAIN). The default is the candidate rule.
struct Crc2Variant {
  enum class Order : std::uint8_t {
    kReversed,  // candidate: the input sequence is fed last byte first (as V2, VERIFIED)
    kForward,   // fed in the order listed
  };
  enum class Preset : std::uint8_t {
    kCrc1,  // candidate: register preset = CRC1 (F_Par_CRC)
    kZero,  // preset 0 (F-parameters not covered)
  };
  enum class SeqCoverage : std::uint8_t {
    kPerCheckSeqNr,  // candidate: consecutive number covered iff F_Check_SeqNr = 1
    kAlways,
    kNever,
  };
  enum class SeqPosition : std::uint8_t {
    kFirst,  // candidate: [number] + F-data + status/control (the V2 order)
    kLast,   // F-data + status/control + [number] (the wire order)
  };
  Order order = Order::kReversed;
  Preset preset = Preset::kCrc1;
  SeqCoverage seq_coverage = SeqCoverage::kPerCheckSeqNr;
  SeqPosition seq_position = SeqPosition::kFirst;

  friend bool operator==(const Crc2Variant&, const Crc2Variant&) = default;
};
[[nodiscard]] const char* to_string(Crc2Variant::Order v) noexcept;
[[nodiscard]] const char* to_string(Crc2Variant::Preset v) noexcept;
[[nodiscard]] const char* to_string(Crc2Variant::SeqCoverage v) noexcept;
[[nodiscard]] const char* to_string(Crc2Variant::SeqPosition v) noexcept;

// How PDUs of one F-device connection look.
struct PduConfig {
  ProtocolVersion version = ProtocolVersion::kV1;
  std::size_t data_size = 1;  // F-data bytes (1..kMaxDataSize)
  std::uint16_t crc1 = 0;     // F_Par_CRC of the connection's F-parameters
  bool check_seqnr = false;   // F_Check_SeqNr (V1)
  bool long_crc2 = false;     // V2 with a 4-byte CRC2 (F_CRC_Length 2); else 3 bytes
  Crc2Variant variant{};      // V1 only; V2 is VERIFIED and fixed

  // From F-parameters: version from F_Par_Version, crc1 from F_Par_CRC, the CRC2 length from
  // F_CRC_Length.
  [[nodiscard]] static PduConfig from(const FParameters& p, std::size_t data_size,
                                      Crc2Variant variant = {}) noexcept;
};

// CRC2 bytes: V1 2, V2 3 or 4.
[[nodiscard]] std::size_t crc2_size(const PduConfig& c) noexcept;
// Total PDU size (data + status/control + [V1: number] + CRC2).
[[nodiscard]] std::size_t pdu_size(const PduConfig& c) noexcept;
// ProfisafeError::kPduDataTooLong / kPduUnsupportedCrcLength if the configuration cannot be used.
[[nodiscard]] std::error_code check_config(const PduConfig& c) noexcept;

// CRC2 of the given content. `consecutive_number`: V1 the 1-byte number (low 8 bits),
// V2 the virtual consecutive number (24 bits used, fed as 4 bytes big-endian).
[[nodiscard]] std::uint32_t crc2(const PduConfig& c, std::span<const std::uint8_t> data,
                                 std::uint8_t status_or_control,
                                 std::uint32_t consecutive_number) noexcept;

// Write one PDU into `out` (at least pdu_size bytes); returns the number of bytes written.
// Errors: kPduWrongSize (data.size() != c.data_size or out too small), config errors.
[[nodiscard]] Result<std::size_t> build_pdu(const PduConfig& c, std::span<const std::uint8_t> data,
                                            std::uint8_t status_or_control,
                                            std::uint32_t consecutive_number,
                                            std::span<std::uint8_t> out) noexcept;

struct PduCheck {
  ProfisafeError error = ProfisafeError::kOk;  // kOk, kPduWrongSize, kPduCrc2Mismatch
  std::span<const std::uint8_t> data;          // F-data (empty on kPduWrongSize)
  std::uint8_t status_or_control = 0;
  std::uint8_t consecutive_number = 0;  // V1: as received; V2: 0 (not sent)
  std::uint32_t received_crc2 = 0;
  std::uint32_t computed_crc2 = 0;
  [[nodiscard]] bool ok() const noexcept { return error == ProfisafeError::kOk; }
};

// Check size and CRC2 of a received PDU. V1: CRC2 is computed over the number as received
// (the caller compares it); V2: `virtual_consecutive_number` is the receiver's expected
// number. Never throws; any byte string is a valid input.
[[nodiscard]] PduCheck check_pdu(const PduConfig& c, std::span<const std::uint8_t> pdu,
                                 std::uint32_t virtual_consecutive_number = 0) noexcept;

// Every combination of the Crc2Variant choices (2 orders x 2 presets x 3 coverages x 2
// positions = 24).
[[nodiscard]] std::vector<Crc2Variant> all_crc2_variants();

// Settle the UNCERTAIN V1 rule from a capture: the variants under which every PDU of
// `pdus` (V1, shaped as `base` says: data size, CRC1, F_Check_SeqNr) checks. An empty
// `pdus` matches everything; a capture with many distinct PDUs leaves one (or none).
[[nodiscard]] std::vector<Crc2Variant> matching_crc2_variants(
    const PduConfig& base, std::span<const std::span<const std::uint8_t>> pdus);

// V1 consecutive numbers run 1..255 and wrap to 1 (0 = none sent yet; DECISION,
// [PROFIsafe V1.30 safety PDU]).
[[nodiscard]] constexpr std::uint8_t next_consecutive_number(std::uint8_t n) noexcept {
  return n >= 255 ? std::uint8_t{1} : static_cast<std::uint8_t>(n + 1);
}
[[nodiscard]] constexpr std::uint8_t previous_consecutive_number(std::uint8_t n) noexcept {
  return n <= 1 ? std::uint8_t{255} : static_cast<std::uint8_t>(n - 1);
}
// V2 virtual consecutive number: 24 bit, wraps 0xFFFFFF → 1.
[[nodiscard]] constexpr std::uint32_t next_virtual_consecutive_number(std::uint32_t n) noexcept {
  return n >= 0xFFFFFFu ? 1u : n + 1u;
}

}  // namespace rs4sim::profisafe
