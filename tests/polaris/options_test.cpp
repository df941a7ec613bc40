#include "polaris/options.h"

#include <gtest/gtest.h>

namespace rs4sim::polaris {
namespace {

TEST(Options, DefaultsAreValid) {
  EXPECT_EQ(Options{}.validate(), "");
  EXPECT_EQ(start_address(Options{}), 0x2000);
  Options master;
  master.role = Role::kMaster;
  EXPECT_EQ(start_address(master), 0);
  EXPECT_EQ(master.validate(), "");
}

TEST(Options, PreciseMessages) {
  Options o;
  o.beams = 17;
  EXPECT_EQ(o.validate(),
            "beams 17: no PL10 model has that many (the family makes 8..344 beams, by its "
            "body heights)");
  o = Options{};
  o.baud = 9600;
  EXPECT_EQ(o.validate(), "baud 9600: the Polaris runs at 19200, 38400, 57600 or 115200");
  o = Options{};
  o.address = 0;
  EXPECT_EQ(o.validate(), "address 0: must be 1..247 (no broadcast)");
  o = Options{};
  o.start_address = 499;
  EXPECT_EQ(o.validate(), "start address 499: must be 500..12287 in slave mode");
  o = Options{};
  o.scan_time = std::chrono::milliseconds(4);
  EXPECT_EQ(o.validate(), "scan time 4 ms: must be 5..5000 ms");
  o = Options{};
  o.pn2_filter = 0;
  EXPECT_EQ(o.validate(), "PN2 filter 0: must be 1..255 scans");
}

TEST(Options, ScanDurationFromBeams) {
  Options o;
  o.family = Family::kPli02;
  o.beams = 1375;
  EXPECT_EQ(scan_duration(o), std::chrono::microseconds(300 + 14 * 1375));  // 19.55 ms
  o.response_time = std::chrono::milliseconds(2);
  EXPECT_EQ(scan_duration(o), std::chrono::milliseconds(2));
}

TEST(Options, DataModeNames) {
  EXPECT_EQ(parse_data_mode("FL10"), DataMode::kFl10);
  EXPECT_EQ(to_string(DataMode::k485Mb), "485MB");
  EXPECT_FALSE(parse_data_mode("FL2"));
}

}  // namespace
}  // namespace rs4sim::polaris
