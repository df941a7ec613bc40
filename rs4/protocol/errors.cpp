#include "rs4/protocol/errors.h"

namespace rs4sim::rs4::protocol {

std::string_view to_string(ProtocolError e) noexcept {
  switch (e) {
    case ProtocolError::kRecordTooShort: return "record too short for a block (§5.1)";
    case ProtocolError::kRecordTooLong: return "record longer than 240 bytes (§5)";
    case ProtocolError::kBlockLengthOutOfRange: return "block length byte out of range (§5.1)";
    case ProtocolError::kBlockLengthExceedsRecord:
      return "block length byte exceeds the record (§5.1)";
    case ProtocolError::kBadFlowControl: return "invalid flow-control byte (§5.2)";
    case ProtocolError::kEmptyCommand: return "WRITE without a command byte (§5.3)";
    case ProtocolError::kBadAnswerCode: return "unexpected answer code (§5.3)";
    case ProtocolError::kBadAnswerLength: return "answer length differs from the spec (§5.3)";
    case ProtocolError::kBadAnswerValue: return "answer field out of range (§5.3)";
    case ProtocolError::kTruncated: return "telegram truncated (§6)";
    case ProtocolError::kTrailingBytes: return "bytes after the end of the telegram (§6)";
    case ProtocolError::kUnknownTelegram: return "unknown RS4 telegram code (§6)";
    case ProtocolError::kBadOptionCount: return "option byte count inconsistent (§6)";
    case ProtocolError::kBadOperatingState: return "undefined operating state in option 1 (§6)";
    case ProtocolError::kReservedBitSet: return "reserved option bit set (§6)";
    case ProtocolError::kZeroOptionByte: return "option 2 transmitted as 0x00 (§6)";
    case ProtocolError::kBadFieldPair: return "field pair number above 4 in option 3 (§6)";
    case ProtocolError::kOption3MarkerMissing: return "option 3 without bit 7 (§6)";
    case ProtocolError::kBadScanNumberFiller: return "scan number filler is not 0xFE (§6.1)";
    case ProtocolError::kBadResolution: return "measurement resolution 0 (§6.1)";
    case ProtocolError::kSegmentOutOfRange: return "segment number above 528 (§6.1)";
    case ProtocolError::kStartAfterStop: return "output start after output stop (§6.1)";
    case ProtocolError::kValueCountMismatch:
      return "value count disagrees with start/stop/resolution (§6.1)";
    case ProtocolError::kEmptyFrame: return "empty RS232 frame body (§11)";
    case ProtocolError::kBadCommandByte: return "RS232 command byte 0x00 or 0xFF (§11)";
    case ProtocolError::kFrameTooShort: return "RS232 frame too short (§11)";
    case ProtocolError::kFrameTooLong: return "RS232 frame too long (§11)";
    case ProtocolError::kStuffingViolation: return "RS232 zero-stuffing violated (§11)";
    case ProtocolError::kBadCheck: return "RS232 check character mismatch (§11)";
    case ProtocolError::kBadAlarmHeader: return "alarm PDU header invalid (§7)";
    case ProtocolError::kBadAlarmSpecifier: return "alarm specifier invalid (§7)";
    case ProtocolError::kBadErrorCode: return "diagnosis alarm code is not 0x84 (§7.2)";
  }
  return "unknown rs4 protocol error";
}

}  // namespace rs4sim::rs4::protocol
