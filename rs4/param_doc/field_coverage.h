#pragma once
// A protective field is never removed by accident: a segment of 0 mm has no protective field
// on its beam ([RS4 manual §2.3]: the protective field is the area the scanner guards; the
// parameter set gives its contour as one distance per segment). Every surface that takes a
// parameter set from a user refuses a protective field with segments left unset unless the
// user says it on purpose (allow_partial_field, docs/param.md "Partial protective fields"):
// a document (Device.SetParameterSet, `rs4sim param set`) whose runs leave segments out, and
// a stored set an archive import or restore would make current whose protective field has
// segments of 0 mm (a stored set keeps no other trace of what was meant).

#include "rs4/param_doc/document_error.h"
#include "rs4/scanner/parameter_set.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace rs4sim::rs4::param_doc {

// The document key, request field and CLI word that say it on purpose.
inline constexpr const char* kAllowPartialField = "allow_partial_field";

struct CoverageOptions {
  bool allow_partial_field = false;
};

// Segments of `protective` at 0 mm.
std::size_t unset_segments(const scanner::Contour& protective);

// The refusal of the protective field at `path` (a JSON path, or "field pair N" of a stored
// set) with `unset` segments left unset: DocumentError::kPartialField with the count and the
// way to say it on purpose; nothing when there are none or the options allow it.
std::optional<DocumentIssue> check_protective_field(std::size_t unset, const std::string& path,
                                                    const CoverageOptions& options);

// Every field pair of a stored set (an archive's): the first refusal.
std::optional<DocumentIssue> check_protective_fields(const scanner::ParameterSet& set,
                                                     const CoverageOptions& options);
// The same for an archived blob (the transfer form the proxy stores); nothing for a blob that
// is not an RS4 parameter set (the archive holds other devices' sets too).
std::optional<DocumentIssue> check_stored_set(std::span<const std::uint8_t> blob,
                                              const CoverageOptions& options);

}  // namespace rs4sim::rs4::param_doc
