// The --mode word list (polaris/mode_spec.h): the PC tool's settings [Polaris manual §7.4.2]
// and the scan time from the user: response-time= and response-column= (the model tables'
// two maximum response time columns [Polaris manual §2.1]), with their range checks.
#include "polaris/mode_spec.h"

#include <gtest/gtest.h>

#include <chrono>

namespace rs4sim::polaris {
namespace {

using std::chrono::microseconds;

Options with(std::string_view spec) {
  Options o;  // PL 10, 16 beams (PL 10-160)
  EXPECT_EQ(apply_mode_spec(spec, o), "") << spec;
  return o;
}

TEST(PolarisModeSpec, StorageWords) {
  const Options o = with("FL4,storage=hole,permanent");
  EXPECT_EQ(o.mode, DataMode::kFl4);
  EXPECT_EQ(o.storage, DataStorage::kHole);
  EXPECT_EQ(o.storage_mode, StorageMode::kPermanent);
  EXPECT_EQ(with("FL1,storage=object,temporary").storage, DataStorage::kObject);
  Options bad;
  EXPECT_EQ(apply_mode_spec("FL1,storage=holes", bad),
            "'storage=holes': storage= takes none, object or hole");
}

// "PL 10-160 ... 0,6 1,0 16" [Polaris manual §2.1]: 16 beams, 0,6 ms and 1,0 ms.
TEST(PolarisModeSpec, ResponseColumnPicksTheTablesSecondColumn) {
  EXPECT_EQ(scan_duration(with("485MB")), microseconds(600));
  EXPECT_EQ(scan_duration(with("485MB,response-column=1")), microseconds(600));
  EXPECT_EQ(scan_duration(with("485MB,response-column=2")), microseconds(1000));
  // response-time= wins over the column.
  EXPECT_EQ(scan_duration(with("485MB,response-column=2,response-time=750")), microseconds(750));
}

TEST(PolarisModeSpec, ResponseTimingRangesBothSides) {
  EXPECT_EQ(with("485MB,response-time=1000000").validate(), "");
  EXPECT_EQ(with("485MB,response-time=1000001").validate(),
            "response time 1000001 us: must be 0 (the model's) .. 1000 ms");
  EXPECT_EQ(with("485MB,response-column=3").validate(),
            "response column 3: the model tables have columns 1 and 2");
  EXPECT_EQ(with("485MB,response-column=0").validate(),
            "response column 0: the model tables have columns 1 and 2");
  Options o;
  EXPECT_EQ(apply_mode_spec("485MB,response-time=-1", o),
            "'response-time=-1': response-time= takes microseconds, 0 (the model's) .. 1000000, "
            "e.g. response-time=600");
}

}  // namespace
}  // namespace rs4sim::polaris
