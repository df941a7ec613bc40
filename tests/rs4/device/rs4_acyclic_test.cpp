// Measurement telegram fetched with PROFI_CMD_GET_RS4_DATA 0x92 + READ (
// [RS4 manual §5.2.2, §5.2.3.4]) and decoded back to the scene's contour.
#include "rs4/protocol/measurement.h"
#include "rs4/protocol/telegram.h"
#include "rs4_fixture.h"

namespace rs4sim::rs4::device::testing {
namespace {

TEST(Rs4Acyclic, MeasurementTelegramMatchesTheScannerContour) {
  Rs4Segment s(segment_config());
  bring_to_ossd_on(s);
  // An object in the warning field only (pair 1: protective 1000 mm, warning 2000 mm).
  ASSERT_TRUE(s.device().scanner().edit_scene(s.now()).add(scanner::Circle{{0, 1500}, 100}));
  s.run_for(200ms);
  const std::vector<std::uint8_t> cmd{
      0x92,  // PROFI_CMD_GET_RS4_DATA
      0x01,  // mask bit 0: measurement telegrams 0x23
      0x00,  // mode 0: forward one telegram
  };
  const auto answer = s.command(cmd);
  ASSERT_TRUE(answer) << answer.error().message();
  const auto& body = answer.value();
  ASSERT_FALSE(body.empty());
  EXPECT_EQ(body[0], 0x23);  // COM_CMD_MESS_16_RT
  auto decoded = protocol::decode_telegram(body);
  ASSERT_TRUE(decoded) << decoded.error().message();
  const auto* m = std::get_if<protocol::MeasurementTelegram>(&decoded.value());
  ASSERT_NE(m, nullptr);
  // Factory measurement output: resolution 1, segments 0..528 → 529 values.
  EXPECT_EQ(m->resolution, 1);
  EXPECT_EQ(m->start, 0);
  EXPECT_EQ(m->stop, 528);
  ASSERT_EQ(m->values.size(), 529U);
  const auto& contour = s.device().scanner().last_scan().contour;  // static scene
  std::size_t near = 0;
  for (std::size_t seg = 0; seg < 529; ++seg) {
    const auto mm = protocol::value_distance_mm(m->values[seg]);
    EXPECT_EQ(mm, contour[seg] & 0xFFFE) << "segment " << seg;
    EXPECT_FALSE(protocol::value_field_violated(m->values[seg])) << "segment " << seg;
    if (mm < 2000) ++near;
  }
  // 90° is segment 14 + 250 = 264: the object straight ahead at ≈1400 mm.
  EXPECT_LT(protocol::value_distance_mm(m->values[264]), 1500);
  EXPECT_GT(near, 3U);
  EXPECT_EQ(m->prefix.options.state, protocol::Option1State::kMeasuring);
}

TEST(Rs4Acyclic, UnknownAdapterChannelRecordIsRefusedWithADpv1Error) {
  Rs4Segment s(segment_config());
  s.power_on();
  ASSERT_TRUE(s.run_until([&] { return s.in_data_exchange(); }, 5s));
  // Slot 0 index 2/3 only ([RS4 manual §5.2]): index 7 → negative response.
  const std::vector<std::uint8_t> rec{0x00, 0x05, 0xFF, 0xFF, 0x84};
  auto id = s.master().write(s.rs4_address(), 0, 7, rec);
  ASSERT_TRUE(id);
  ASSERT_TRUE(s.run_until([&] { return !events_of<dp::master::Dpv1Result>(s).empty(); }, 2s));
  EXPECT_TRUE(events_of<dp::master::Dpv1Result>(s).front().error);
}

}  // namespace
}  // namespace rs4sim::rs4::device::testing
