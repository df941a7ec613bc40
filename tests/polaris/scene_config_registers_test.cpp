// polaris::Scene (which physical beams are interrupted) and the configuration registers'
// pure functions (EXTENSION, polaris/config_registers.h), without a device.
#include "polaris/config_registers.h"
#include "polaris/device.h"
#include "polaris/scene.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <vector>

namespace rs4sim::polaris {
namespace {

using Beams = std::vector<std::uint16_t>;

TEST(PolarisScene, SetsAndListsAscending) {
  Scene s(40);
  EXPECT_FALSE(s.any_interrupted());
  const Beams beams{34, 9, 10};
  ASSERT_FALSE(s.set_interrupted(beams));
  EXPECT_EQ(s.interrupted(), (Beams{9, 10, 34}));
  EXPECT_TRUE(s.any_interrupted());
  EXPECT_EQ(s.flags().size(), 40U);
  EXPECT_EQ(s.flags()[8], 1);
  EXPECT_EQ(s.flags()[10], 0);
}

// The initial scene is in the options, as the GridScan's and the METRON's are; the barrier
// sees it from its start (PN2's hole filter counts from there).
TEST(PolarisScene, TheInitialSceneIsAnOption) {
  Options o;  // PL 10-160
  o.blocked = {3, 9};
  o.detection = Detection::kHole;
  o.pn2_filter = 2;
  EXPECT_EQ(o.validate(), "");
  Device d(o);
  EXPECT_EQ(d.interrupted(), (Beams{3, 9}));
  const stream::TimePoint t0 = stream::TimePoint{} + std::chrono::seconds(5);
  d.on_time(t0);
  EXPECT_FALSE(d.pn2(t0 + 2 * d.scan() - std::chrono::nanoseconds(1)));
  EXPECT_TRUE(d.pn2(t0 + 2 * d.scan()));
  o.blocked = {17};
  EXPECT_EQ(o.validate(), "blocked beam 17 outside 1..16");
}

TEST(PolarisScene, RefusesBeamZeroAndBeyondAndKeepsTheOldScene) {
  Scene s(40);
  const Beams old{5};
  ASSERT_FALSE(s.set_interrupted(old));
  const Beams zero{3, 0};
  const Beams past{40, 41};
  EXPECT_EQ(s.set_interrupted(zero), SceneError::kNoSuchBeam);
  EXPECT_EQ(s.set_interrupted(past), SceneError::kNoSuchBeam);
  EXPECT_EQ(s.interrupted(), old);
  const Beams edge{1, 40};
  EXPECT_FALSE(s.set_interrupted(edge));
  EXPECT_EQ(s.interrupted(), edge);
}

TEST(PolarisConfigRegisters, MapsEachRefusalToItsException) {
  using modbus::ExceptionCode;
  EXPECT_EQ(exception_for(ConfigError::kUnknownRegister), ExceptionCode::kIllegalDataAddress);
  EXPECT_EQ(exception_for(ConfigError::kReadOnly), ExceptionCode::kIllegalDataAddress);
  EXPECT_EQ(exception_for(ConfigError::kBadQuantity), ExceptionCode::kIllegalDataValue);
  EXPECT_EQ(exception_for(ConfigError::kOutOfRange), ExceptionCode::kIllegalDataValue);
  EXPECT_EQ(exception_for(ConfigError::kInvalidOptions), ExceptionCode::kIllegalDataValue);
  EXPECT_EQ(exception_for(ConfigError::kBusy), ExceptionCode::kServerDeviceBusy);
}

TEST(PolarisConfigRegisters, EachRangeBothSides) {
  struct Case {
    ConfigRegister reg;
    std::uint16_t min;
    std::uint16_t max;
  };
  for (const Case c : {Case{ConfigRegister::kDataMode, 0, 3}, Case{ConfigRegister::kStartAddress, 500, 12287},
                       Case{ConfigRegister::kDirection, 0, 1}, Case{ConfigRegister::kDetection, 0, 1},
                       Case{ConfigRegister::kPn2Filter, 1, 255}, Case{ConfigRegister::kScanTime, 5, 5000},
                       Case{ConfigRegister::kBitOrder, 0, 1}, Case{ConfigRegister::kNakMode, 0, 1},
                       Case{ConfigRegister::kCommand, 0, 2}}) {
    const auto at = static_cast<std::uint16_t>(c.reg);
    SCOPED_TRACE(at);
    ConfigWrite w;
    EXPECT_FALSE(write_config(Options{}, at, Beams{c.min}, w));
    EXPECT_FALSE(write_config(Options{}, at, Beams{c.max}, w));
    EXPECT_EQ(write_config(Options{}, at, Beams{static_cast<std::uint16_t>(c.max + 1)}, w),
              ConfigError::kOutOfRange);
    if (c.min > 0) {
      EXPECT_EQ(write_config(Options{}, at, Beams{static_cast<std::uint16_t>(c.min - 1)}, w),
                ConfigError::kOutOfRange);
    }
  }
}

TEST(PolarisConfigRegisters, AWriteThatLeavesInvalidOptionsIsRefused) {
  Options broken;
  broken.beams = 17;  // no PL 10 model has 17 beams: validate() refuses it
  ConfigWrite w;
  w.options.pn2_filter = 99;
  EXPECT_EQ(write_config(broken, static_cast<std::uint16_t>(ConfigRegister::kPn2Filter),
                         Beams{3}, w),
            ConfigError::kInvalidOptions);
  EXPECT_EQ(w.options.pn2_filter, 99);  // untouched
}

TEST(PolarisConfigRegisters, CommandZeroDoesNothingOneStartsCalibration) {
  const auto at = static_cast<std::uint16_t>(ConfigRegister::kCommand);
  ConfigWrite w;
  ASSERT_FALSE(write_config(Options{}, at, Beams{0}, w));
  EXPECT_FALSE(w.start_calibration);
  ASSERT_FALSE(write_config(Options{}, at, Beams{kCommandStartCalibration}, w));
  EXPECT_TRUE(w.start_calibration);
}

TEST(PolarisConfigRegisters, ReadCountsAndBounds) {
  std::vector<std::uint16_t> out;
  const CalibrationStatus idle;
  EXPECT_EQ(read_config(Options{}, idle, kConfigBase, 0, out), ConfigError::kBadQuantity);
  EXPECT_EQ(read_config(Options{}, idle, kConfigBase, 126, out), ConfigError::kBadQuantity);
  EXPECT_EQ(read_config(Options{}, idle, kConfigBase, 13, out), ConfigError::kUnknownRegister);
  EXPECT_EQ(read_config(Options{}, idle, kConfigBase - 1, 1, out), ConfigError::kUnknownRegister);
  ASSERT_FALSE(read_config(Options{}, CalibrationStatus{true, 7}, kConfigBase + 9, 3, out));
  EXPECT_EQ(out, (std::vector<std::uint16_t>{1, 7, 16}));  // calibrating, 7 done, 16 beams
}

}  // namespace
}  // namespace rs4sim::polaris
