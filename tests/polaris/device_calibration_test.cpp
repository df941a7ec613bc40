// Auto-calibration started by the command register 0x0108 (EXTENSION) or from outside (the
// autocal input, SW1): it lasts 0.4 s x N beams [Polaris manual §7.2] on the manual clock,
// data reads meanwhile get exception 06 Server Device Busy (DECISION,
// docs/decisions.md#polaris-calibration-busy), and the status registers say when it ended.
// The detection area must be free: "Make sure that there is no material to be detected or
// other obstacles in the detection area" [Polaris manual §7.2], so the scene is empty while
// a calibration runs, and a start with beams interrupted is refused.
// CRCs computed independently (CRC-16/MODBUS, low byte first).
#include "modbus/timing.h"
#include "tests/polaris/polaris_line.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <vector>

namespace rs4sim::polaris {
namespace {

using std::chrono::milliseconds;
using std::chrono::nanoseconds;
using std::chrono::seconds;
using namespace testing;  // Answers, answers, Bytes, Rig

const Bytes kStartCal{0x01, 0x06,   // slave 1, FC 6
                      0x01, 0x08,   // register 0x0108 command
                      0x00, 0x01,   // 1: start auto-calibration
                      0xC8, 0x34};  // CRC
const Bytes kReadStatus{0x01, 0x03, 0x01, 0x09, 0x00, 0x02, 0x15, 0xF5};  // 0x0109, 2 words
const Bytes kCalibrating{0x01, 0x03, 0x04,
                         0x00, 0x01,   // status: calibrating
                         0x00, 0x00,   // calibrations completed: 0
                         0xAB, 0xF3};  // CRC
const Bytes kCalibratedOnce{0x01, 0x03, 0x04,
                            0x00, 0x00,   // status: idle
                            0x00, 0x01,   // calibrations completed: 1
                            0x3B, 0xF3};  // CRC
const Bytes kReadData{0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xCB};  // FL1 block
const Bytes kData{0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28};  // 9..34
const Bytes kEmptyData{0x01, 0x03, 0x04,
                       0x00, 0x00,   // first: no object
                       0x00, 0x00,   // last: no object
                       0xFA, 0x33};  // CRC
const Bytes kBusy{0x01, 0x83, 0x06, 0xC1, 0x32};  // FC 3 | 0x80, 06 Server Device Busy

// Beams 9 and 34 interrupted: the FL1 data 9..34 (kData).
void interrupt_edges(Rig& r) {
  const std::vector<std::uint16_t> beams{9, 34};
  EXPECT_FALSE(r.device().set_interrupted(beams, r.now()));
}

// A request that arrives at `at` is decided t3.5 later (the frame's end).
stream::Duration t3_5(Rig& r) { return modbus::t3_5(r.device().line_settings()); }

// The device receives `request` whole at `at` (send() at `at`: no wire time) and the rig's
// 100 ms window runs from there; the answers as answers() gives them. Nothing may have
// reached the controller or be on the wire between the last exchange and `at`: a frame the
// slave gave out meanwhile would be an answer nobody asked for.
Answers answers_at(Rig& r, const Bytes& request, stream::TimePoint at) {
  r.run_to(at);
  EXPECT_TRUE(r.quiet()) << "frames before the request";
  return answers(r, request);
}

Options cal_options() {
  Options o;  // PL 10, 40 beams, FL1, slave 1
  o.beams = 40;
  o.mode = DataMode::kFl1;
  return o;
}

// Starts calibration by the command register; returns when it must end.
stream::TimePoint start_by_command(Rig& r) {
  const stream::TimePoint sent = r.now();
  EXPECT_EQ(answers(r, kStartCal), (Answers{kStartCal}));  // echoed
  return sent + t3_5(r) + seconds(16);  // 0.4 s x 40 beams from the request's end
}

TEST(PolarisCalibration, LastsPointFourSecondsPerBeam) {
  EXPECT_EQ(Device(cal_options()).calibration_time(), seconds(16));  // 0.4 s x 40
  Options pli = cal_options();
  pli.family = Family::kPli02;
  pli.beams = 1375;
  EXPECT_EQ(Device(pli).calibration_time(), milliseconds(550'000));  // 0.4 s x 1375
}

TEST(PolarisCalibration, DataReadOneTickBeforeTheEndIsBusy) {
  Rig r(cal_options());
  const stream::TimePoint end = start_by_command(r);
  EXPECT_EQ(answers(r, kReadStatus), (Answers{kCalibrating}));
  // The read's end (last byte + t3.5) one nanosecond before the calibration's.
  EXPECT_EQ(answers_at(r, kReadData, end - t3_5(r) - nanoseconds(1)), (Answers{kBusy}));
  EXPECT_EQ(r.device().counters().busy, 1U);
  EXPECT_EQ(r.device().counters().requests, 1U);  // the status read
}

TEST(PolarisCalibration, DataReadAtTheEndGetsData) {
  Rig r(cal_options());
  const stream::TimePoint end = start_by_command(r);
  EXPECT_TRUE(r.device().calibrating(end - nanoseconds(1)));
  EXPECT_FALSE(r.device().calibrating(end));
  EXPECT_EQ(r.device().calibration_end(), end);
  EXPECT_EQ(answers_at(r, kReadData, end - t3_5(r)), (Answers{kEmptyData}));
  EXPECT_EQ(answers(r, kReadStatus), (Answers{kCalibratedOnce}));
  EXPECT_EQ(r.device().calibrations(), 1U);
  EXPECT_EQ(r.device().counters().busy, 0U);
}

TEST(PolarisCalibration, TheStatusFlipsAtTheEndWithoutARequest) {
  Rig r(cal_options());
  const stream::TimePoint end = start_by_command(r);
  r.run_to(end - nanoseconds(1));
  EXPECT_EQ(r.device().calibrations(), 0U);
  r.run_to(end);  // the end is one of the core's deadlines
  EXPECT_EQ(r.device().calibrations(), 1U);
  EXPECT_EQ(r.device().calibration_end(), std::nullopt);
}

TEST(PolarisCalibration, SecondStartIsBusyOtherWritesAndFc4Too) {
  Rig r(cal_options());
  start_by_command(r);
  EXPECT_EQ(answers(r, kStartCal), (Answers{{0x01, 0x86, 0x06, 0xC2, 0x62}}));
  EXPECT_EQ(r.device().counters().refused_writes, 1U);
  // FC 4 of the data block: 06 as well.
  EXPECT_EQ(answers(r, {0x01, 0x04, 0x20, 0x00, 0x00, 0x02, 0x7A, 0x0B}),
            (Answers{{0x01, 0x84, 0x06, 0xC3, 0x02}}));
  // A setting is taken meanwhile (DECISION): data mode FL4.
  const Bytes fl4{0x01, 0x06, 0x01, 0x00, 0x00, 0x02, 0x09, 0xF7};
  EXPECT_EQ(answers(r, fl4), (Answers{fl4}));
  EXPECT_EQ(r.device().options().mode, DataMode::kFl4);
  EXPECT_EQ(r.device().start_calibration(r.now()),
            std::make_error_code(std::errc::device_or_resource_busy));
}

// A real-time runner's timer can fire late: the autocal pulse may be handled before the
// device's deadline for a read that had already ended (its t3.5 passed). That read ended
// before the calibration began, so it is answered with data, not 06. The device is driven
// by hand here, since no line would let a deadline pass unserved.
TEST(PolarisCalibration, AReadThatEndedBeforeThePulseGetsData) {
  Device d(cal_options());
  const stream::TimePoint t0{};
  d.on_time(t0);
  d.on_bytes(kReadData, t0);
  const stream::TimePoint late = t0 + milliseconds(10);  // t3.5 (1.82 ms) long gone
  ASSERT_FALSE(d.start_calibration(late));
  EXPECT_EQ(d.calibration_end(), late + seconds(16));
  std::vector<Bytes> sent;
  for (int i = 0; i < 8; ++i) {
    while (auto f = d.take_transmit()) sent.push_back(*f);
    const auto next = d.next_deadline();
    if (!next || *next >= late + seconds(1)) break;
    d.on_time(*next);
  }
  EXPECT_EQ(sent, (std::vector<Bytes>{kEmptyData}));
}

TEST(PolarisCalibration, MasterSendsNothingWhileCalibrating) {
  Options o = cal_options();
  o.role = Role::kMaster;
  o.beams = 8;  // PL 10-80: 3.2 s
  o.scan_time = milliseconds(20);
  Rig r(o);
  const stream::TimePoint t0 = r.now();
  r.run_to(t0 + milliseconds(30));  // the push at 20 ms
  ASSERT_FALSE(r.device().start_calibration(r.now()));
  r.run_to(t0 + milliseconds(3250));
  const auto got = r.take();
  ASSERT_EQ(got.size(), 2U);
  EXPECT_EQ(got[0].start, t0 + milliseconds(20));
  // Pushes due at 40 .. 3220 ms fall inside 30 ms + 3.2 s; the next goes out at 3240 ms.
  EXPECT_EQ(got[1].start, t0 + milliseconds(3240));
  // That push (13 characters, 6.8 ms) has arrived; no later one is on the wire at 3250 ms.
  EXPECT_EQ(got[1].end - got[1].start, testing::chars(r, 13));
  EXPECT_FALSE(r.on_the_wire());
  EXPECT_EQ(r.device().calibrations(), 1U);
}

// "If the green LED does not turn on, check that there are no obstacles in the detection
// area" [Polaris manual §7.2]: with a beam interrupted the procedure does not start; the
// command register's start is refused with exception 04 Server Device Failure (DECISION,
// docs/decisions.md#polaris-calibration-obstacles), the outside start with kBeamsInterrupted.
TEST(PolarisCalibrationObstacles, AStartWithBeamsInterruptedIsRefused) {
  Rig r(cal_options());
  interrupt_edges(r);
  EXPECT_EQ(answers(r, kStartCal), (Answers{{0x01, 0x86, 0x04, 0x43, 0xA3}}));  // FC 6 | 0x80, 04
  EXPECT_EQ(r.device().start_calibration(r.now()), ConfigError::kBeamsInterrupted);
  EXPECT_EQ(r.device().calibration_end(), std::nullopt);
  EXPECT_EQ(answers(r, kReadData), (Answers{kData}));  // measuring, not busy
  EXPECT_EQ(r.device().counters().refused_writes, 1U);
  // The area cleared: the same command starts it.
  ASSERT_FALSE(r.device().set_interrupted({}, r.now()));
  EXPECT_EQ(answers(r, kStartCal), (Answers{kStartCal}));
  EXPECT_TRUE(r.device().calibrating(r.now()));
}

// An obstacle that enters while the beams are adjusted makes the calibration fail: it ends
// at once, is not counted as completed, and data reads are answered again.
TEST(PolarisCalibrationObstacles, AnObstacleDuringTheCalibrationMakesItFail) {
  Rig r(cal_options());
  const stream::TimePoint end = start_by_command(r);
  r.run_to(end - seconds(1));
  ASSERT_TRUE(r.device().calibrating(r.now()));
  interrupt_edges(r);
  EXPECT_FALSE(r.device().calibrating(r.now()));
  EXPECT_EQ(r.device().calibration_end(), std::nullopt);
  EXPECT_EQ(r.device().calibrations_failed(), 1U);
  EXPECT_EQ(answers(r, kReadData), (Answers{kData}));
  r.run_to(end + seconds(1));
  EXPECT_EQ(r.device().calibrations(), 0U);
}

// "close the SW1 contact for at least 0.5 seconds and no more than 3 seconds" starts the
// auto-calibration; "keeping the SW1 contact closed for more than 3 seconds" activates the
// manual adjustment [Polaris manual §7.2]. Both sides of both bounds.
TEST(PolarisSw1, HeldHalfASecondToThreeSecondsStartsTheCalibration) {
  for (const auto held : {milliseconds(500), milliseconds(3000)}) {
    Device d(cal_options());
    const stream::TimePoint t0{};
    d.on_time(t0);
    ASSERT_FALSE(d.set_sw1(true, t0));
    ASSERT_FALSE(d.set_sw1(false, t0 + held));
    EXPECT_EQ(d.calibration_end(), t0 + held + seconds(16)) << held.count();
    EXPECT_FALSE(d.manual_adjustment());
  }
}

TEST(PolarisSw1, HeldLessThanHalfASecondDoesNothing) {
  Device d(cal_options());
  const stream::TimePoint t0{};
  ASSERT_FALSE(d.set_sw1(true, t0));
  ASSERT_FALSE(d.set_sw1(false, t0 + milliseconds(500) - nanoseconds(1)));
  EXPECT_EQ(d.calibration_end(), std::nullopt);
  EXPECT_FALSE(d.manual_adjustment());
}

TEST(PolarisSw1, HeldLongerThanThreeSecondsEntersManualAdjustment) {
  Rig r(cal_options());
  const stream::TimePoint t0 = r.now();
  ASSERT_FALSE(r.device().set_sw1(true, t0));
  ASSERT_FALSE(r.device().set_sw1(false, t0 + seconds(3) + nanoseconds(1)));
  EXPECT_TRUE(r.device().manual_adjustment());
  EXPECT_EQ(r.device().calibration_end(), std::nullopt);
  // The status register (0x0109) reads 2: manual adjustment.
  EXPECT_EQ(answers(r, {0x01, 0x03, 0x01, 0x09, 0x00, 0x01, 0x55, 0xF4}),
            (Answers{{0x01, 0x03, 0x02, 0x00, 0x02, 0x39, 0x85}}));
  // An auto-calibration (short press) leaves it.
  ASSERT_FALSE(r.device().set_sw1(true, r.now()));
  ASSERT_FALSE(r.device().set_sw1(false, r.now() + seconds(1)));
  EXPECT_FALSE(r.device().manual_adjustment());
}

// "the manual adjustment can be activated by sending the ModBus command"
// [Polaris manual §7.2]: the command register's 2 (EXTENSION), echoed.
TEST(PolarisSw1, TheCommandRegistersTwoEntersManualAdjustment) {
  Rig r(cal_options());
  const Bytes manual{0x01, 0x06, 0x01, 0x08, 0x00, 0x02, 0x88, 0x35};
  EXPECT_EQ(answers(r, manual), (Answers{manual}));
  EXPECT_TRUE(r.device().manual_adjustment());
  EXPECT_EQ(r.device().calibration_end(), std::nullopt);
}

// [Polaris manual §5.1]: TX yellow = powered; RX green free, red occupied.
// [Polaris manual §7.2]: while calibrating the yellow LED "flashes quickly", the RX green LED
// "turns on for 5 seconds and then flashes red/green until the auto-calibration is finished".
TEST(PolarisLeds, FollowTheAreaAndTheCalibration) {
  Rig r(cal_options());
  const stream::TimePoint t0 = r.now();
  EXPECT_EQ(r.device().leds(t0), (Leds{Led::kYellow, Led::kGreen}));
  interrupt_edges(r);
  EXPECT_EQ(r.device().leds(t0), (Leds{Led::kYellow, Led::kRed}));
  ASSERT_FALSE(r.device().set_interrupted({}, t0));
  ASSERT_FALSE(r.device().start_calibration(t0));
  EXPECT_EQ(r.device().leds(t0), (Leds{Led::kYellowFlashing, Led::kGreen}));
  EXPECT_EQ(r.device().leds(t0 + seconds(5) - nanoseconds(1)),
            (Leds{Led::kYellowFlashing, Led::kGreen}));
  EXPECT_EQ(r.device().leds(t0 + seconds(5)), (Leds{Led::kYellowFlashing, Led::kRedGreen}));
  EXPECT_EQ(r.device().leds(t0 + seconds(16) - nanoseconds(1)),
            (Leds{Led::kYellowFlashing, Led::kRedGreen}));
  EXPECT_EQ(r.device().leds(t0 + seconds(16)), (Leds{Led::kYellow, Led::kGreen}));
  EXPECT_EQ(to_token(Led::kRedGreen), "red-green");
}

}  // namespace
}  // namespace rs4sim::polaris
