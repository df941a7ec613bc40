#include "rs4/param_doc/document_error.h"

namespace rs4sim::rs4::param_doc {

std::string_view to_string(DocumentError e) noexcept {
  switch (e) {
    case DocumentError::kSyntax: return "parameter document is not valid JSON";
    case DocumentError::kWrongType: return "value of the wrong JSON type";
    case DocumentError::kUnknownKey: return "unknown key in the parameter document";
    case DocumentError::kMissingKey: return "required key missing";
    case DocumentError::kUnsupportedFormat: return "unsupported parameter document format";
    case DocumentError::kOutOfRange: return "value out of range";
    case DocumentError::kPasswordInDocument: return "a parameter document never carries passwords";
    case DocumentError::kBadShape: return "shape does not describe an area";
    case DocumentError::kContourOutOfRange: return "contour beyond the scanner's range";
    case DocumentError::kInvalidSet: return "the scanner's validation refused the set";
    case DocumentError::kPartialField: return "protective field segments left unset";
  }
  return "unknown parameter document error";
}

}  // namespace rs4sim::rs4::param_doc
