// The factory default's summary, written by hand from docs/rs4-scanner.md "Factory
// default": type 0x0004, firmware 1.0, n = 0 (80 ms), restart mode 2, start pair 1, every
// transition permitted, warning output 0x01, measurement 1/0/528, pair p protective
// 1000 + 500·(p−1) mm and warning + 1000 mm on all 529 segments.
#include "rs4/report/parameter_summary.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::report {
namespace {

std::string pair_json(int pair, int protective, int warning) {
  const auto stats = [](int mm) {
    return "{\"min_mm\":" + std::to_string(mm) + ",\"max_mm\":" + std::to_string(mm) +
           ",\"active_segments\":529}";
  };
  return "{\"pair\":" + std::to_string(pair) + ",\"protective\":" + stats(protective) +
         ",\"warning\":" + stats(warning) + "}";
}

TEST(ParameterSummary, FactoryDefaultJson) {
  const std::string expected =
      R"({"format":2,"device_type":"0x0004","serial_number":"0","firmware":"1.0",)"
      R"("response_time_ms":80,)"
      R"("restart_mode":"start_restart_interlock","start_pair":1,)"
      R"("permitted":[[1,2,3,4],[1,2,3,4],[1,2,3,4],[1,2,3,4]],)"
      R"("warning_output":["contamination"],"measurement":{"resolution":1,"start":0,"stop":528},)"
      R"("pairs":[)" +
      pair_json(1, 1000, 2000) + "," + pair_json(2, 1500, 2500) + "," + pair_json(3, 2000, 3000) +
      "," + pair_json(4, 2500, 3500) + "]}";
  EXPECT_EQ(summary_json(scanner::factory_default()), expected);
}

TEST(ParameterSummary, OptionsAndPartialContours) {
  auto set = scanner::factory_default();
  set.identity.serial_number = 4711;
  set.response_steps = 2;  // 80 + 2·40 = 160 ms
  set.restart_mode = scanner::RestartMode::kAutomatic;
  set.permitted[1] = 0x06;  // from pair 2: to 2 and 3
  set.warning_output = scanner::kWarnOnWarningField | scanner::kWarnOnFault;
  set.pairs[3].protective_mm.fill(0);
  set.pairs[3].warning_mm.fill(0);
  set.pairs[3].warning_mm[10] = 700;
  set.pairs[3].warning_mm[11] = 9000;
  const std::string json = summary_json(set);
  EXPECT_NE(json.find(R"("serial_number":"4711")"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("response_time_ms":160,"restart_mode":"automatic")"), std::string::npos);
  EXPECT_NE(json.find(R"("permitted":[[1,2,3,4],[2,3],)"), std::string::npos);
  EXPECT_NE(json.find(R"("warning_output":["warning_field","fault"])"), std::string::npos);
  EXPECT_NE(json.find(R"({"pair":4,"protective":{"min_mm":0,"max_mm":0,"active_segments":0},)"
                      R"("warning":{"min_mm":700,"max_mm":9000,"active_segments":2}})"),
            std::string::npos)
      << json;
}

TEST(ParameterSummary, NeverShowsPasswords) {
  auto set = scanner::factory_default();
  set.passwords[0] = {'S', 'E', 'C', 'R', 'E', 'T', 'X', 'Y'};
  EXPECT_EQ(summary_json(set), summary_json(scanner::factory_default()));
  EXPECT_EQ(summary_text(set).find("SECRET"), std::string::npos);
  EXPECT_EQ(summary_text(set).find("password"), std::string::npos);
}

TEST(ParameterSummary, Text) {
  const std::string text = summary_text(scanner::factory_default());
  EXPECT_NE(text.find("  response time        80 ms\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  pair 2 protective     1500.. 1500 mm on 529 segments\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  warning output       contamination\n"), std::string::npos);
}

}  // namespace
}  // namespace rs4sim::rs4::report
