#include "rs4/protocol/errors.h"

namespace rs4sim::rs4::protocol {

std::string_view to_string(ProtocolError e) noexcept {
  switch (e) {
    case ProtocolError::kRecordTooShort:
      return "record too short for a block ([RS4 manual §5.2.1])";
    case ProtocolError::kRecordTooLong: return "record longer than 240 bytes ([RS4 manual §5.2])";
    case ProtocolError::kBlockLengthOutOfRange:
      return "block length byte out of range ([RS4 manual §5.2.1])";
    case ProtocolError::kBlockLengthExceedsRecord:
      return "block length byte exceeds the record ([RS4 manual §5.2.1])";
    case ProtocolError::kBadFlowControl: return "invalid flow-control byte ([RS4 manual §5.2.1])";
    case ProtocolError::kEmptyCommand: return "WRITE without a command byte ([RS4 manual §5.2.2])";
    case ProtocolError::kBadAnswerCode: return "unexpected answer code ([RS4 manual §5.2.2])";
    case ProtocolError::kBadAnswerLength:
      return "answer length differs from the manual ([RS4 manual §5.2.2])";
    case ProtocolError::kBadAnswerValue: return "answer field out of range ([RS4 manual §5.2.2])";
    case ProtocolError::kTruncated: return "telegram truncated ([RS4 manual §5.2.3])";
    case ProtocolError::kTrailingBytes:
      return "bytes after the end of the telegram ([RS4 manual §5.2.3])";
    case ProtocolError::kUnknownTelegram: return "unknown RS4 telegram code ([RS4 manual §5.2.3])";
    case ProtocolError::kBadOptionCount:
      return "option byte count inconsistent ([RS4 manual §5.2.3])";
    case ProtocolError::kBadOperatingState:
      return "undefined operating state in option 1 ([RS4 manual §5.2.3])";
    case ProtocolError::kReservedBitSet: return "reserved option bit set ([RS4 manual §5.2.3])";
    case ProtocolError::kZeroOptionByte:
      return "option 2 transmitted as 0x00 ([RS4 manual §5.2.3])";
    case ProtocolError::kBadFieldPair:
      return "field pair number above 4 in option 3 ([RS4 manual §5.2.3])";
    case ProtocolError::kOption3MarkerMissing:
      return "option 3 without bit 7 ([RS4 manual §5.2.3])";
    case ProtocolError::kBadScanNumberFiller:
      return "scan number filler is not 0xFE ([RS4 manual §5.2.3.4])";
    case ProtocolError::kBadResolution: return "measurement resolution 0 ([RS4 manual §5.2.3.4])";
    case ProtocolError::kSegmentOutOfRange:
      return "segment number above 528 ([RS4 manual §5.2.3.4])";
    case ProtocolError::kStartAfterStop:
      return "output start after output stop ([RS4 manual §5.2.3.4])";
    case ProtocolError::kValueCountMismatch:
      return "value count disagrees with start/stop/resolution ([RS4 manual §5.2.3.4])";
    case ProtocolError::kEmptyFrame:
      return "empty RS232 frame body ([roboticslibrary/rl LeuzeRs4.cpp])";
    case ProtocolError::kBadCommandByte:
      return "RS232 command byte 0x00 or 0xFF ([roboticslibrary/rl LeuzeRs4.cpp])";
    case ProtocolError::kFrameTooShort:
      return "RS232 frame too short ([roboticslibrary/rl LeuzeRs4.cpp])";
    case ProtocolError::kFrameTooLong:
      return "RS232 frame too long ([roboticslibrary/rl LeuzeRs4.cpp])";
    case ProtocolError::kStuffingViolation:
      return "RS232 zero-stuffing violated ([roboticslibrary/rl LeuzeRs4.cpp])";
    case ProtocolError::kBadCheck:
      return "RS232 check character mismatch ([roboticslibrary/rl LeuzeRs4.cpp])";
    case ProtocolError::kBadAlarmHeader: return "alarm PDU header invalid ([RS4 manual §5.3])";
    case ProtocolError::kBadAlarmSpecifier: return "alarm specifier invalid ([RS4 manual §5.3])";
    case ProtocolError::kBadErrorCode:
      return "diagnosis alarm code is not 0x84 ([RS4 manual §5.3.2])";
  }
  return "unknown rs4 protocol error";
}

}  // namespace rs4sim::rs4::protocol
