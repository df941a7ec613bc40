#pragma once
// Typed errors of the scanner model, each an enum class carried as std::error_code with
// its own category ([docs/design.md#error-codes]).

#include "codec/error_category.h"

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::rs4::scanner {

// Semantic check of a ParameterSet (docs/rs4-scanner.md "Validation").
enum class ParameterError : std::uint8_t {
  kProtectiveTooFar = 1,   // protective contour > 4000 mm ([RS4 manual §2.3, §2.4])
  kWarningTooFar,          // warning contour > 15000 mm ([docs/decisions.md#rs4-extensions],
                           // project limit)
  kResponseTimeSteps,      // n in 80 ms + n·40 ms above kMaxResponseSteps
  kRestartMode,            // unknown start/restart interlock mode
  kStartPair,              // start pair not in 1..4
  kTransitionDiagonal,     // a pair must permit staying on itself
  kWarningOutput,          // unknown bit in the warning output assignment
  kMeasurementResolution,  // resolution 0
  kMeasurementRange,       // start > stop or stop > 528
  kPassword,               // byte not printable ASCII / 0xFF padding not at the end
  kEmptyStartField,        // the start pair has no protective field at all
};

// Syntax errors of the binary parameter-set encoding (parameter_codec.h).
enum class CodecError : std::uint8_t {
  kTooShort = 1,        // fewer bytes than the fixed layout
  kTooLong,             // bytes after the fixed layout
  kBadMagic,            // not "RS4P"
  kUnsupportedVersion,  // format version other than 1
  kReservedNotZero,     // a reserved byte is not 0
};

// Scene edits (scene.h).
enum class SceneError : std::uint8_t {
  kNotFinite = 1,     // NaN or infinite coordinate
  kBadRadius,         // circle radius <= 0
  kTooFewVertices,    // polygon with < 3 vertices
  kDegenerateWall,    // wall of zero length
  kRawContourSize,    // raw contour not exactly 529 values
  kUnknownObstacle,   // id not in the scene
  kNotMovable,        // a raw contour has no position
  kTooManyObstacles,  // more than Scene::kMaxObstacles
};

// Control API of the Scanner (scanner.h).
enum class ScannerError : std::uint8_t {
  kNotInConfiguration = 1,  // parameter set may change only in configuration state or off
  kInvalidParameterSet,     // validation failed (see validate())
  kNotMeasuring,            // configuration entered only from measuring/error
  kUnknownFault,            // a Fault value outside the enumeration
};

[[nodiscard]] std::string_view to_string(ParameterError e) noexcept;
[[nodiscard]] std::string_view to_string(CodecError e) noexcept;
[[nodiscard]] std::string_view to_string(SceneError e) noexcept;
[[nodiscard]] std::string_view to_string(ScannerError e) noexcept;
constexpr const char* error_category_name(ParameterError) noexcept {
  return "rs4.scanner.parameter";
}
constexpr const char* error_category_name(CodecError) noexcept { return "rs4.scanner.codec"; }
constexpr const char* error_category_name(SceneError) noexcept { return "rs4.scanner.scene"; }
constexpr const char* error_category_name(ScannerError) noexcept { return "rs4.scanner"; }
inline std::error_code make_error_code(ParameterError e) noexcept {
  return codec::make_error_code_of(e);
}
inline std::error_code make_error_code(CodecError e) noexcept {
  return codec::make_error_code_of(e);
}
inline std::error_code make_error_code(SceneError e) noexcept {
  return codec::make_error_code_of(e);
}
inline std::error_code make_error_code(ScannerError e) noexcept {
  return codec::make_error_code_of(e);
}

}  // namespace rs4sim::rs4::scanner
