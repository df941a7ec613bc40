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

// By default a scan lasts the model's first maximum response time
// [Polaris manual §2.1, §2.2] (PLi 02-3440: 19,6 ms; PL 10-160: 0,6 ms; PL 10-3040: 8,7 ms).
TEST(Options, ScanDurationIsTheModelsResponseTime) {
  using std::chrono::microseconds;
  Options o;
  EXPECT_EQ(scan_duration(o), microseconds(600));
  o.family = Family::kPli02;
  o.beams = 1375;
  EXPECT_EQ(scan_duration(o), microseconds(19600));
  o.family = Family::kPl10;
  o.beams = 304;
  EXPECT_EQ(scan_duration(o), microseconds(8700));
  o.beams = 305;  // no such model (validate() refuses it): the next larger one's, PL 10-3120
  EXPECT_EQ(scan_duration(o), microseconds(8900));
  o.beams = 400;  // above the family: its largest
  EXPECT_EQ(scan_duration(o), microseconds(9800));
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
