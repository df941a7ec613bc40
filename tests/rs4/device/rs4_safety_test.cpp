// Protective field, restart interlock, field-pair switching and the diagnosis alarm
// ([RS4 manual §2.3, §2.4, §5.1.2, §5.3.2]; response time [RS4 manual §6.6]).
#include "rs4/protocol/adapter_error.h"
#include "rs4/scanner/faults.h"
#include "rs4_fixture.h"

namespace rs4sim::rs4::device::testing {
namespace {

scanner::Shape intruder(double distance_mm) { return scanner::Circle{{0, distance_mm}, 50}; }

TEST(Rs4Safety, ObjectInProtectiveFieldSwitchesOssdOffWithinResponseTime) {
  Rs4Segment s(segment_config());
  bring_to_ossd_on(s);
  const auto id = s.device().scanner().edit_scene(s.now()).add(intruder(600));  // pair 1: 1000 mm
  ASSERT_TRUE(id);
  const auto at = s.now();
  // The device side first: its OSSD bit follows the RS4, whose OSSDs go off at the 2nd
  // consecutive violated 40 ms scan (T_scanner 80 ms), 10 ms later (the adapter's response time).
  const auto device = time_until(s, [&] { return !s.device().adapter().ossd_bit(); }, 1s);
  ASSERT_TRUE(device.has_value());
  EXPECT_GE(*device, 40ms + 10ms) << "not before a whole violated scan has passed";
  EXPECT_LE(*device, 80ms + 10ms);
  ASSERT_TRUE(s.run_until([&] { return (s.input_byte() & kInputOssd) == 0; }, 1s));
  const auto t = s.now() - at;
  // [RS4 manual §6.6]: T_R = T_scanner + T_WD; T_scanner = 80 ms (factory), T_WD = F_WD_Time
  // 150 ms: the master's OSSD bit goes no later, and not before the device's.
  EXPECT_LE(t, 80ms + 150ms);
  EXPECT_GE(t, *device);
  EXPECT_NE(s.input_byte() & kInputProtectiveField, 0);
}

TEST(Rs4Safety, RestartInterlockHoldsOssdOffUntilARestartPulse) {
  Rs4Segment s(segment_config());
  bring_to_ossd_on(s);
  auto& scene = s.device().scanner().edit_scene(s.now());
  const auto id = scene.add(intruder(600));
  ASSERT_TRUE(id);
  ASSERT_TRUE(s.run_until([&] { return (s.input_byte() & kInputOssd) == 0; }, 1s));
  ASSERT_TRUE(s.device().scanner().edit_scene(s.now()).remove(id.value()));
  ASSERT_TRUE(s.run_until([&] { return (s.input_byte() & kInputProtectiveField) == 0; }, 1s));
  s.run_for(2s);
  EXPECT_EQ(s.input_byte() & kInputOssd, 0);  // interlock: field free, OSSD still off
  s.set_output_byte(kOutputRestart | 0x01);
  s.run_for(200ms);
  EXPECT_EQ(s.input_byte() & kInputOssd, 0);  // while restart is held, OSSD off
                                              // ([RS4 manual §2.3, §2.4])
  s.set_output_byte(0x01);
  EXPECT_TRUE(s.run_until([&] { return (s.input_byte() & kInputOssd) != 0; }, 500ms));
}

TEST(Rs4Safety, PermittedFieldPairSwitchKeepsOssdOn) {
  Rs4Segment s(segment_config());
  bring_to_ossd_on(s);
  s.set_output_byte(0x02);  // field pair 2 ([RS4 manual §5.1.2]: 010)
  ASSERT_TRUE(s.run_until([&] { return s.device().scanner().status().first_pair == 2; }, 500ms));
  s.run_for(500ms);
  EXPECT_NE(s.input_byte() & kInputOssd, 0);
  // Pair 2 guards 1500 mm: an object at 1200 mm violates it (it would not violate pair 1).
  ASSERT_TRUE(s.device().scanner().edit_scene(s.now()).add(intruder(1200)));
  EXPECT_TRUE(s.run_until([&] { return (s.input_byte() & kInputOssd) == 0; }, 500ms));
}

TEST(Rs4Safety, InvalidFieldPairGives0x2600AndReleaseAbout500msAfterAValidOne) {
  Rs4Segment s(segment_config());
  bring_to_ossd_on(s);
  s.set_output_byte(0x05);  // 101: no field pair ([RS4 manual §5.1.2])
  ASSERT_TRUE(s.run_until([&] { return (s.input_byte() & kInputOssd) == 0; }, 500ms));
  const auto& mem = s.device().adapter().error_memory();
  EXPECT_GT(
      mem.count(adapter::Processor::kUc1, 0x2600) + mem.count(adapter::Processor::kUc2, 0x2600), 0);
  s.run_for(1s);
  EXPECT_EQ(s.input_byte() & kInputOssd, 0);
  s.set_output_byte(0x03);  // valid pair 3
  const auto t = time_until(
      s, [&] { return (s.input_byte() & kInputOssd) != 0; }, 2s);
  ASSERT_TRUE(t.has_value());
  EXPECT_GE(*t, 500ms);
  EXPECT_LE(*t, 500ms + 100ms);  // + scan, adapter and bus cycles
}

TEST(Rs4Safety, Rs4ErrorGivesDiagnosisAlarmComingThenGoing) {
  Rs4Segment s(segment_config());
  bring_to_ossd_on(s);
  s.take_events();
  const auto fault = scanner::Fault::kDazzled;
  ASSERT_TRUE(s.device().scanner().inject_fault(fault, s.now()));
  ASSERT_TRUE(s.run_until([&] { return !events_of<dp::master::AlarmReceived>(s).empty(); }, 1s));
  const auto coming = events_of<dp::master::AlarmReceived>(s).front();
  EXPECT_EQ(coming.alarm_type, 0x01);  // diagnosis alarm ([RS4 manual §5.3.2])
  EXPECT_EQ(coming.slot, 0x00);
  EXPECT_NE(coming.specifier & 0x04, 0);     // bit 2: acknowledge required
  EXPECT_EQ(coming.specifier & 0x03, 0x01);  // DECISION: 01 = appears
  ASSERT_GE(coming.data.size(), 9U);
  EXPECT_EQ(coming.data[0], 0x84);  // "error from slave"
  const std::uint16_t number = scanner::fault_info(fault).error_number;
  EXPECT_EQ(coming.data[1], number >> 8);    // μC2 (RS4) error number hi
  EXPECT_EQ(coming.data[2], number & 0xFF);  // lo
  EXPECT_TRUE(s.run_until([&] { return (s.input_byte() & kInputOssd) == 0; }, 500ms));
  s.take_events();
  // The cause goes; the fault stays latched until the restart button acknowledges it
  // ([RS4 manual §2.3, §2.4]).
  ASSERT_TRUE(s.device().scanner().clear_fault(fault, s.now()));
  s.run_for(1s);
  EXPECT_TRUE(events_of<dp::master::AlarmReceived>(s).empty());
  s.set_output_byte(kOutputRestart | 0x01);
  s.run_for(200ms);
  s.set_output_byte(0x01);
  ASSERT_TRUE(s.run_until([&] { return !s.device().scanner().status().fault; }, 500ms));
  const auto cleared = s.now();
  ASSERT_TRUE(s.run_until([&] { return !events_of<dp::master::AlarmReceived>(s).empty(); }, 3s));
  const auto going = events_of<dp::master::AlarmReceived>(s).front();
  EXPECT_EQ(going.alarm_type, 0x01);
  EXPECT_EQ(going.specifier & 0x03, 0x02);  // DECISION: 10 = disappears
  EXPECT_GE(s.now() - cleared, 500ms);      // ≥ 500 ms without an error ([RS4 manual §5.3.2])
}

}  // namespace
}  // namespace rs4sim::rs4::device::testing

namespace rs4sim::rs4::device::testing {
namespace {

// [RS4 manual §6.2, §6.3] passivation ([RS4 manual §7.3.2]): a CRC2 error → substitute value 0
// (OSSD reads 0), ACK_REQ once communication is healthy, ACK_REI reintegrates.
TEST(Rs4Safety, CommunicationErrorPassivatesUntilAckRei) {
  Rs4Segment s(segment_config());
  bring_to_ossd_on(s);
  s.device().adapter().safety_faults().corrupt_crc2 = 1;
  ASSERT_TRUE(s.run_until([&] { return s.fhost().passivated(); }, 200ms));
  EXPECT_EQ(s.input_byte(), 0);  // substitute value
  ASSERT_TRUE(s.run_until([&] { return s.fhost().ack_req(); }, 200ms));
  s.run_for(1s);
  EXPECT_EQ(s.input_byte(), 0);  // stays passivated without the user acknowledgement
  // The passivated host sends fail-safe values 0: output byte 0 is field pair 0, so the
  // device itself reports the switching error (0x2600) and holds its OSSD bit at 0.
  EXPECT_FALSE(s.device().adapter().ossd_bit());
  s.ack_rei();
  // Pair 1 again: released ≈500 ms later ([RS4 manual §5.1.2]), then seen through the F-host.
  const auto t = time_until(
      s, [&] { return (s.input_byte() & kInputOssd) != 0; }, 1s);
  ASSERT_TRUE(t.has_value());
  EXPECT_LE(*t, 650ms);
  EXPECT_EQ(s.fhost().counters().crc_errors, 1U);
}

TEST(Rs4Safety, AutoAckReiOptionReintegratesAtOnce) {
  auto c = segment_config();
  c.auto_ack_rei = true;
  Rs4Segment s(c);
  bring_to_ossd_on(s);
  const auto before = s.fhost().counters().reintegrations;
  s.device().adapter().safety_faults().corrupt_crc2 = 1;
  ASSERT_TRUE(s.run_until([&] { return s.fhost().passivated(); }, 200ms));
  EXPECT_TRUE(s.run_until([&] { return (s.input_byte() & kInputOssd) != 0; }, 200ms));
  EXPECT_EQ(s.fhost().counters().reintegrations, before + 1);  // the ACK_REI after the fault
}

}  // namespace
}  // namespace rs4sim::rs4::device::testing
