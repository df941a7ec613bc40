#pragma once
// Typed decode/encode errors of the RS4 wire formats ([RS4 manual §5.2, §5.2.3, §5.3],
// [roboticslibrary/rl LeuzeRs4.cpp]). The adapter's own error numbers (table 5.3-3) are
// AdapterError in adapter_error.h; this category covers malformed bytes and invalid values handed
// to an encoder. Carried as std::error_code with the category "rs4.protocol".

#include "codec/error_category.h"

#include <boost/outcome/std_result.hpp>

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::rs4::protocol {

// Every decoder returns Result<T>: the value or a std::error_code, never throws on
// malformed wire input.
template <typename T>
using Result = boost::outcome_v2::std_result<T>;

enum class ProtocolError : std::uint8_t {
  // --- block header, [RS4 manual §5.2.1] ---
  kRecordTooShort = 1,        // record shorter than the 4-byte header (READ) / 5 bytes (WRITE)
  kRecordTooLong,             // record longer than 240 bytes ([RS4 manual §5.2] "max 240")
  kBlockLengthOutOfRange,     // header byte 2 outside 5..240 (WRITE) / 4..240 (READ)
  kBlockLengthExceedsRecord,  // header byte 2 describes more bytes than the record holds
  kBadFlowControl,            // reserved bit 2/3/7 set or state outside 001..101
                              // ([RS4 manual §5.2.1])
  // --- adapter commands and answers, [RS4 manual §5.2.2] ---
  kEmptyCommand,     // WRITE payload without a command byte
  kBadAnswerCode,    // answer does not start with the expected code byte
  kBadAnswerLength,  // answer length differs from the manual's table
  kBadAnswerValue,   // a field of an answer outside its range
  // --- RS4 telegrams, [RS4 manual §5.2.3] ---
  kTruncated,             // telegram ends inside a field
  kTrailingBytes,         // bytes after the last field of a fixed-size telegram
  kUnknownTelegram,       // command byte is none of 0x14, 0x23, 0x53, 0x54
  kBadOptionCount,        // option 1 bits 1..0 = 0, or disagreeing with option 2 bit 7
  kBadOperatingState,     // option 1 bits 4..2 = 101..111
  kReservedBitSet,        // option 1 bit 7 or option 3 bit 6 set
  kZeroOptionByte,        // option 2 transmitted as 0x00 ([RS4 manual §5.2.3] "never 0x00")
  kBadFieldPair,          // option 3 field pair > 4
  kOption3MarkerMissing,  // option 3 without bit 7 = 1
  kBadScanNumberFiller,   // scan number filler byte is not 0xFE ([RS4 manual §5.2.3.4])
  kBadResolution,         // resolution 0
  kSegmentOutOfRange,     // start or stop > 528
  kStartAfterStop,        // start > stop
  kValueCountMismatch,    // values disagree with start/stop/resolution
  // --- RS232 framing, [roboticslibrary/rl LeuzeRs4.cpp] ---
  kEmptyFrame,         // framer: nothing to send
  kBadCommandByte,     // CMD 0x00 or 0xFF ([roboticslibrary/rl LeuzeRs4.cpp] "never 0x00 or 0xFF")
  kFrameTooShort,      // fewer than CMD, OPT1 and CHK between start and end
  kFrameTooLong,       // body longer than the deframer's limit
  kStuffingViolation,  // after 00 00 inside a frame neither 0xFF nor the end zero
  kBadCheck,           // XOR check character mismatch
  // --- alarm PDUs, [RS4 manual §5.3] ---
  kBadAlarmHeader,     // length/type/slot bytes are not the manual's constants
  kBadAlarmSpecifier,  // specifier bits 7..6 set or bit 2 (ack) clear
  kBadErrorCode,       // diagnosis alarm byte 5 is not 0x84
};

[[nodiscard]] std::string_view to_string(ProtocolError e) noexcept;
constexpr const char* error_category_name(ProtocolError) noexcept { return "rs4.protocol"; }
inline std::error_code make_error_code(ProtocolError e) noexcept {
  return codec::make_error_code_of(e);
}

}  // namespace rs4sim::rs4::protocol
