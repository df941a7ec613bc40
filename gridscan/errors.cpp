#include "gridscan/errors.h"

namespace rs4sim::gridscan {

std::string_view to_string(FrameError e) noexcept {
  switch (e) {
    case FrameError::kTooShort: return "frame shorter than 10 bytes";
    case FrameError::kTooLong: return "frame longer than 20 bytes";
    case FrameError::kBadSync: return "sync pattern is not 43 45 44 45";
    case FrameError::kBadCrc: return "CRC-32 mismatch";
    case FrameError::kRequestPayload: return "request carries a payload";
    case FrameError::kDirectionBit: return "direction bit wrong for the frame's direction";
    case FrameError::kUnknownId: return "unknown command ID";
    case FrameError::kPayloadLength: return "payload length does not fit the ID";
    case FrameError::kBadField: return "payload field out of range";
  }
  return "unknown gridscan frame error";
}

}  // namespace rs4sim::gridscan
