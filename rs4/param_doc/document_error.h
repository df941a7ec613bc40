#pragma once
// Why a parameter document was refused (docs/param.md "Errors"): a typed code carried as
// std::error_code, the JSON path of the offending value ("$.pairs.2.protective.runs[0].mm")
// and a reason that names the limit and its source.

#include "codec/error_category.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

namespace rs4sim::rs4::param_doc {

enum class DocumentError : std::uint8_t {
  kSyntax = 1,          // not JSON
  kWrongType,           // e.g. a string where a number belongs
  kUnknownKey,          // a key the format does not define
  kMissingKey,          // a key the format requires (format, a shape's parameter)
  kUnsupportedFormat,   // "format" other than 1
  kOutOfRange,          // a value outside its limits
  kPasswordInDocument,  // a document never carries passwords
  kBadShape,            // a shape that does not describe an area
  kContourOutOfRange,   // a contour beyond the scanner's range for that field
  kInvalidSet,          // the scanner's own validation refused the resulting set
  kPartialField,        // a protective field with segments left unset (field_coverage.h)
};

[[nodiscard]] std::string_view to_string(DocumentError e) noexcept;
constexpr const char* error_category_name(DocumentError) noexcept { return "rs4.param_doc"; }
inline std::error_code make_error_code(DocumentError e) noexcept {
  return codec::make_error_code_of(e);
}

struct DocumentIssue {
  DocumentError error{};
  std::string path;    // JSON path, "$" = the document
  std::string reason;  // human text with the limit
  // "$.response_time_ms: 100 is not 80 + n·40 ms ..."
  [[nodiscard]] std::string message() const { return path + ": " + reason; }
};

}  // namespace rs4sim::rs4::param_doc

template <>
struct std::is_error_code_enum<rs4sim::rs4::param_doc::DocumentError> : std::true_type {};
