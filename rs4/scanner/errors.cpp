#include "rs4/scanner/errors.h"

namespace rs4sim::rs4::scanner {

std::string_view to_string(ParameterError e) noexcept {
  switch (e) {
    case ParameterError::kProtectiveTooFar: return "protective contour beyond 4000 mm";
    case ParameterError::kWarningTooFar: return "warning contour beyond 15000 mm";
    case ParameterError::kResponseTimeSteps: return "response time steps out of range";
    case ParameterError::kRestartMode: return "unknown start/restart interlock mode";
    case ParameterError::kStartPair: return "start field pair not in 1..4";
    case ParameterError::kTransitionDiagonal: return "a field pair must permit itself";
    case ParameterError::kWarningOutput: return "unknown warning output assignment bit";
    case ParameterError::kMeasurementResolution: return "measurement resolution 0";
    case ParameterError::kMeasurementRange: return "measurement start/stop out of range";
    case ParameterError::kPassword: return "password byte not printable ASCII or padding";
    case ParameterError::kEmptyStartField: return "start field pair has no protective field";
  }
  return "unknown parameter error";
}

std::string_view to_string(CodecError e) noexcept {
  switch (e) {
    case CodecError::kTooShort: return "parameter set encoding too short";
    case CodecError::kTooLong: return "bytes after the parameter set encoding";
    case CodecError::kBadMagic: return "parameter set magic is not RS4P";
    case CodecError::kUnsupportedVersion: return "unsupported parameter set format version";
    case CodecError::kReservedNotZero: return "reserved byte not zero";
  }
  return "unknown codec error";
}

std::string_view to_string(SceneError e) noexcept {
  switch (e) {
    case SceneError::kNotFinite: return "coordinate not finite";
    case SceneError::kBadRadius: return "circle radius must be > 0";
    case SceneError::kTooFewVertices: return "polygon needs at least 3 vertices";
    case SceneError::kDegenerateWall: return "wall has zero length";
    case SceneError::kRawContourSize: return "raw contour must have 529 values";
    case SceneError::kUnknownObstacle: return "no obstacle with this id";
    case SceneError::kNotMovable: return "a raw contour cannot be moved";
    case SceneError::kTooManyObstacles: return "too many obstacles in the scene";
  }
  return "unknown scene error";
}

std::string_view to_string(ScannerError e) noexcept {
  switch (e) {
    case ScannerError::kNotInConfiguration: return "scanner not in configuration state";
    case ScannerError::kInvalidParameterSet: return "parameter set failed validation";
    case ScannerError::kNotMeasuring: return "scanner not measuring";
    case ScannerError::kUnknownFault: return "unknown fault";
  }
  return "unknown scanner error";
}

}  // namespace rs4sim::rs4::scanner
