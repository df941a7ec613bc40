// A protective field is never removed by accident (rs4/param_doc/field_coverage.h). Known
// answer from the issue that found it: one run for segments 100..140 leaves 529 - 41 = 488
// segments of the protective field unset, and was accepted.
#include "rs4/param_doc/field_coverage.h"
#include "rs4/param_doc/parameter_document.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::param_doc {
namespace {

constexpr const char* kOneRun = R"({"format": 1, "pairs": {"2": {"protective": {"runs": [
    {"from": 100, "to": 140, "mm": 1850}]}}}})";

TEST(FieldCoverage, ADocumentWhoseRunsLeaveProtectiveSegmentsUnsetIsRefusedWithTheCount) {
  const auto r = from_document(kOneRun, scanner::factory_default());
  ASSERT_FALSE(r);
  EXPECT_EQ(r.issue.error, DocumentError::kPartialField);
  EXPECT_EQ(r.issue.path, "$.pairs.2.protective.runs");
  EXPECT_NE(r.issue.reason.find("488 of 529 segments"), std::string::npos) << r.issue.reason;
  EXPECT_NE(r.issue.reason.find("allow_partial_field"), std::string::npos) << r.issue.reason;
}

TEST(FieldCoverage, AllowPartialFieldSaysItOnPurpose) {
  const auto r = from_document(kOneRun, scanner::factory_default(), {true});
  ASSERT_TRUE(r) << r.issue.message();
  EXPECT_EQ(r.set->pairs[1].protective_mm[99], 0);
  EXPECT_EQ(r.set->pairs[1].protective_mm[100], 1850);
  EXPECT_EQ(r.set->pairs[1].protective_mm[141], 0);
}

TEST(FieldCoverage, RunsOverEverySegmentAShapeAndAWarningFieldAreNotPartial) {
  const auto base = scanner::factory_default();
  EXPECT_TRUE(from_document(R"({"format": 1, "pairs": {"2": {"protective": {"runs": [
      {"from": 0, "to": 99, "mm": 1500}, {"from": 100, "to": 528, "mm": 0}]}}}})",
                            base));  // an explicit 0 is said on purpose
  EXPECT_TRUE(from_document(R"({"format": 1, "pairs": {"1": {"protective":
      {"sector": {"radius_mm": 3000, "from_deg": 0, "to_deg": 90}}}}})",
                            base));  // 0 outside the sector is the shape's meaning
  EXPECT_TRUE(from_document(R"({"format": 1, "pairs": {"1": {"warning": {"runs": [
      {"from": 0, "to": 10, "mm": 3000}]}}}})",
                            base));
}

TEST(FieldCoverage, AStoredSetIsCheckedByItsZeroSegments) {
  auto set = scanner::factory_default();
  EXPECT_FALSE(check_protective_fields(set, {}));
  for (std::size_t n = 0; n < 488; ++n) set.pairs[2].protective_mm[n] = 0;
  const auto issue = check_protective_fields(set, {});
  ASSERT_TRUE(issue);
  EXPECT_EQ(issue->path, "field pair 3");
  EXPECT_NE(issue->reason.find("488 of 529"), std::string::npos) << issue->reason;
  EXPECT_FALSE(check_protective_fields(set, {true}));
}

}  // namespace
}  // namespace rs4sim::rs4::param_doc
