#pragma once
// The RS4 parameter set as a human-editable JSON document (docs/param.md): the field pairs
// with their contours (runs of equal distance, 529 values, or a simple shape, see
// contour_shapes.h), response time, restart mode, permitted field switching, warning output
// and measurement output ([RS4 manual §2.3, §4.3, §5.1.1, §5.1.2, §5.2.3.4, §6.6]). The
// device identity is shown, read-only; passwords are never written and never read
// ([RS4 manual §7.2.4]): a document that names one is refused.

#include "rs4/param_doc/document_error.h"
#include "rs4/param_doc/field_coverage.h"
#include "rs4/scanner/parameter_set.h"

#include <optional>
#include <string>
#include <string_view>

namespace rs4sim::rs4::param_doc {

inline constexpr int kDocumentFormat = 1;  // the "format" key

// The whole set, every key present, contours as runs; pretty-printed, ends with '\n'.
// Deterministic: one set, one text.
std::string to_document(const scanner::ParameterSet& set);

struct DocumentResult {
  std::optional<scanner::ParameterSet> set;  // engaged on success
  DocumentIssue issue;                       // the refusal otherwise
  explicit operator bool() const { return set.has_value(); }
};

// `base` with what the document says. Keys the document leaves out keep `base`'s value
// (pairs and contours one by one); identity and passwords always stay `base`'s. The result
// passed the scanner's own validate() (parameter_set.h) and, for every protective contour the
// document gives, check_protective_field() (field_coverage.h; a segment no run covers is
// 0 mm); otherwise the first problem with its JSON path and reason.
DocumentResult from_document(std::string_view json, const scanner::ParameterSet& base,
                             const CoverageOptions& coverage = {});

}  // namespace rs4sim::rs4::param_doc
