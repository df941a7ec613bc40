#include "dp/fdl/errors.h"

namespace rs4sim::dp::fdl {

std::string_view to_string(DecodeError e) noexcept {
  switch (e) {
    case DecodeError::kGarbage: return "byte outside a frame (no start delimiter)";
    case DecodeError::kLengthMismatch: return "SD2 length LE differs from repeated LEr";
    case DecodeError::kLengthOutOfRange: return "SD2 length LE outside 3..249";
    case DecodeError::kStartDelimiterMismatch: return "SD2 repeated start delimiter is not 0x68";
    case DecodeError::kBadEndDelimiter: return "end delimiter is not 0x16";
    case DecodeError::kBadFcs: return "frame check sequence mismatch";
    case DecodeError::kBadFrameControl: return "reserved frame control code";
    case DecodeError::kBadAddressExtension: return "unsupported or missing address extension byte";
    case DecodeError::kSapWithoutPartner: return "DSAP without SSAP (or SSAP without DSAP)";
    case DecodeError::kBadTokenAddress: return "token address with extension bit set";
    case DecodeError::kTruncated: return "line idle inside a frame";
  }
  return "unknown FDL decode error";
}

}  // namespace rs4sim::dp::fdl
