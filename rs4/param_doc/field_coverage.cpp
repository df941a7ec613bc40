#include "rs4/param_doc/field_coverage.h"

#include "rs4/scanner/parameter_codec.h"

#include <algorithm>

namespace rs4sim::rs4::param_doc {

std::size_t unset_segments(const scanner::Contour& protective) {
  return static_cast<std::size_t>(std::count(protective.begin(), protective.end(), 0));
}

std::optional<DocumentIssue> check_protective_field(std::size_t unset, const std::string& path,
                                                    const CoverageOptions& options) {
  if (unset == 0 || options.allow_partial_field) return std::nullopt;
  return DocumentIssue{DocumentError::kPartialField, path,
                       std::to_string(unset) + " of " + std::to_string(scanner::kSegmentCount) +
                           " segments of the protective field are left unset (0 mm: no "
                           "protective field on those beams [RS4 manual §2.3]); give every "
                           "segment a distance, or say it on purpose with " +
                           kAllowPartialField};
}

std::optional<DocumentIssue> check_protective_fields(const scanner::ParameterSet& set,
                                                     const CoverageOptions& options) {
  for (std::size_t p = 0; p < set.pairs.size(); ++p) {
    auto issue = check_protective_field(unset_segments(set.pairs[p].protective_mm),
                                        "field pair " + std::to_string(p + 1), options);
    if (issue) return issue;
  }
  return std::nullopt;
}

std::optional<DocumentIssue> check_stored_set(std::span<const std::uint8_t> blob,
                                              const CoverageOptions& options) {
  const auto decoded = scanner::decode_transfer_form(blob);
  if (decoded.has_error()) return std::nullopt;
  return check_protective_fields(decoded.value(), options);
}

}  // namespace rs4sim::rs4::param_doc
