// Validation of the parameter set (EXTENSION, docs/rs4-scanner.md "Validation"): every
// rule has a negative test that names the field, pair, segment and limit.
#include "rs4/scanner/parameter_set.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::scanner {
namespace {

TEST(ScannerParameterSet, FactoryDefaultIsValid) {
  const ParameterSet s = factory_default();
  EXPECT_FALSE(validate(s).has_value());
  EXPECT_EQ(s.start_pair, 1);
  EXPECT_EQ(s.restart_mode, RestartMode::kStartRestartInterlock);
  EXPECT_EQ(s.warning_output, kWarnOnContamination);  // [RS4 manual §5.1.1] recommendation
  EXPECT_EQ(s.pairs[0].protective_mm[0], 1000);
  EXPECT_EQ(s.pairs[3].warning_mm[528], 3500);
}

TEST(ScannerParameterSet, ResponseTimeIs80PlusNTimes40) {
  ParameterSet s = factory_default();
  EXPECT_EQ(response_time(s).count(), 80);
  EXPECT_EQ(scans_to_switch_off(s), 2U);
  s.response_steps = 3;
  EXPECT_EQ(response_time(s).count(), 200);
  EXPECT_EQ(scans_to_switch_off(s), 5U);
}

TEST(ScannerParameterSet, ProtectiveBeyond4mNamesPairSegmentAndLimit) {
  ParameterSet s = factory_default();
  s.pairs[2].protective_mm[77] = 4001;
  const auto issue = validate(s);
  ASSERT_TRUE(issue.has_value());
  EXPECT_EQ(issue->error, ParameterError::kProtectiveTooFar);
  EXPECT_EQ(issue->field, "pairs[].protective_mm");
  EXPECT_EQ(issue->pair, 3);
  EXPECT_EQ(issue->segment, 77);
  EXPECT_EQ(issue->value, 4001U);
  EXPECT_EQ(issue->limit, 4000U);
  EXPECT_NE(issue->message().find("segment/byte 77"), std::string::npos);
  s.pairs[2].protective_mm[77] = 4000;  // the limit itself is valid
  EXPECT_FALSE(validate(s).has_value());
}

TEST(ScannerParameterSet, WarningBeyond15m) {
  ParameterSet s = factory_default();
  s.pairs[0].warning_mm[528] = 15001;
  const auto issue = validate(s);
  ASSERT_TRUE(issue.has_value());
  EXPECT_EQ(issue->error, ParameterError::kWarningTooFar);
  EXPECT_EQ(issue->pair, 1);
  EXPECT_EQ(issue->segment, 528);
  EXPECT_EQ(issue->limit, 15000U);
}

struct Case {
  const char* name;
  void (*mutate)(ParameterSet&);
  ParameterError error;
  const char* field;
};

const Case kCases[] = {
    {"response_steps", [](ParameterSet& s) { s.response_steps = 15; },
     ParameterError::kResponseTimeSteps, "response_steps"},
    {"restart_mode", [](ParameterSet& s) { s.restart_mode = static_cast<RestartMode>(3); },
     ParameterError::kRestartMode, "restart_mode"},
    {"start_pair_0", [](ParameterSet& s) { s.start_pair = 0; }, ParameterError::kStartPair,
     "start_pair"},
    {"start_pair_5", [](ParameterSet& s) { s.start_pair = 5; }, ParameterError::kStartPair,
     "start_pair"},
    {"diagonal", [](ParameterSet& s) { s.permitted[1] = 0x0D; },
     ParameterError::kTransitionDiagonal, "permitted"},
    {"row_high_bits", [](ParameterSet& s) { s.permitted[0] = 0x1F; },
     ParameterError::kTransitionDiagonal, "permitted"},
    {"warning_output", [](ParameterSet& s) { s.warning_output = 0x10; },
     ParameterError::kWarningOutput, "warning_output"},
    {"resolution", [](ParameterSet& s) { s.measurement.resolution = 0; },
     ParameterError::kMeasurementResolution, "measurement.resolution"},
    {"stop_529", [](ParameterSet& s) { s.measurement.stop = 529; },
     ParameterError::kMeasurementRange, "measurement.stop"},
    {"start_after_stop",
     [](ParameterSet& s) {
       s.measurement = {4, 10, 9};
     },
     ParameterError::kMeasurementRange, "measurement.start"},
    {"password_ctrl", [](ParameterSet& s) { s.passwords[1][0] = 0x07; }, ParameterError::kPassword,
     "passwords[]"},
    {"password_gap",
     [](ParameterSet& s) { s.passwords[0] = {'A', 0xFF, 'B', 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}; },
     ParameterError::kPassword, "passwords[]"},
    {"empty_start", [](ParameterSet& s) { s.pairs[0].protective_mm.fill(0); },
     ParameterError::kEmptyStartField, "pairs[].protective_mm"},
};

TEST(ScannerParameterSet, EveryRuleRejectsWithItsError) {
  for (const Case& c : kCases) {
    ParameterSet s = factory_default();
    c.mutate(s);
    const auto issue = validate(s);
    ASSERT_TRUE(issue.has_value()) << c.name;
    EXPECT_EQ(issue->error, c.error) << c.name;
    EXPECT_EQ(issue->field, c.field) << c.name;
  }
}

TEST(ScannerParameterSet, ValidPasswordAndTransitionsAccepted) {
  ParameterSet s = factory_default();
  s.passwords[0] = {'R', 'O', 'D', '4', 'L', 'E', 0xFF, 0xFF};  // ASCII then padding
  s.permitted = {0x01, 0x03, 0x04, 0x0F};                       // diagonal always set
  EXPECT_FALSE(validate(s).has_value());
  EXPECT_TRUE(permits(s, 2, 1));
  EXPECT_FALSE(permits(s, 1, 2));
  EXPECT_FALSE(permits(s, 3, 1));
  EXPECT_FALSE(permits(s, 0, 1));
  EXPECT_FALSE(permits(s, 4, 5));
}

TEST(ScannerParameterSet, MergeDownloadKeepsPasswordsAndIdentity) {
  ParameterSet device = factory_default();
  device.passwords[0] = {'S', 'E', 'C', 'R', 'E', 'T', 0xFF, 0xFF};
  device.identity.serial_number = 111;
  ParameterSet incoming = factory_default();
  incoming.passwords[0] = {'O', 'T', 'H', 'E', 'R', 0xFF, 0xFF, 0xFF};
  incoming.identity.serial_number = 222;
  incoming.response_steps = 4;
  const ParameterSet merged = merge_download(device, incoming);
  EXPECT_EQ(merged.passwords, device.passwords);
  EXPECT_EQ(merged.identity.serial_number, 111U);
  EXPECT_EQ(merged.response_steps, 4);
}

}  // namespace
}  // namespace rs4sim::rs4::scanner
