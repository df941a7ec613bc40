// The RS232 port's behaviour on the manual clock: the 0x23 stream period, the line-time
// skip, the acknowledge and password rules, bad input and the detached port (docs/rs232.md).
#include "rs232_fixture.h"
#include "rs4/protocol/rs232.h"
#include "rs4/protocol/telegram.h"
#include "rs4/rs232/rs232_client.h"
#include "tests/rs4/adapter/adapter_rig.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::rs232::testing {
namespace {

const CommandOptions kAckWithPassword{.acknowledge = true, .password = make_password("ROD4LE")};

std::vector<std::uint32_t> scan_numbers(const std::vector<Bytes>& frames) {
  std::vector<std::uint32_t> out;
  for (const auto& f : frames) {
    const auto a = PortFixture::decode(f);
    if (const auto* m = std::get_if<protocol::MeasurementTelegram>(&a))
      out.push_back(m->scan_number);
  }
  return out;
}

// A fixture with a narrow window (67 values: ≈26 ms of line time at 57 600 baud) set over RS232.
struct Streaming : PortFixture {
  Streaming() {
    boot();
    port.attach(clock.now());
    const auto frames = feed(encode_measurement_window(8, 0, 528, kAckWithPassword).value());
    const auto a = decode(frames.at(0));
    EXPECT_TRUE(std::get<Acknowledge>(a).positive);
    (void)run_for(1ms);
  }
};

TEST(Rs232Port, StreamsEveryScanAtTheScanRate) {
  Streaming f;
  const auto skipped = f.port.counters().scans_skipped_busy;  // behind the attach-time frame
  const auto frames = f.run_for(400ms);
  const auto scans = scan_numbers(frames);
  ASSERT_EQ(scans.size(), 10U);  // 400 ms / 40 ms
  for (std::size_t i = 1; i < scans.size(); ++i) EXPECT_EQ(scans[i], scans[i - 1] + 1);
  EXPECT_EQ(f.port.counters().scans_skipped_busy, skipped);
}

TEST(Rs232Port, StreamFramesAre40msApart) {
  Streaming f;
  std::vector<stream::TimePoint> at;
  for (int i = 0; i < 200 && at.size() < 4; ++i) {
    const auto next = f.port.next_deadline();
    ASSERT_TRUE(next);
    f.clock.set(*next);
    f.port.on_time(*next);
    if (!f.drain().empty()) at.push_back(*next);
  }
  ASSERT_EQ(at.size(), 4U);
  for (std::size_t i = 1; i < at.size(); ++i) EXPECT_EQ(at[i] - at[i - 1], 40ms);
}

TEST(Rs232Port, FullContourAt57600SkipsScansWhileTheLineIsBusy) {
  PortFixture f;  // factory window: 529 values, a ≈1.08 kB frame, ≈188 ms at 57 600 baud
  f.boot();
  f.port.attach(f.clock.now());
  const auto scans = scan_numbers(f.run_for(1000ms));
  ASSERT_GE(scans.size(), 4U);
  ASSERT_LE(scans.size(), 6U);
  EXPECT_GE(scans[1] - scans[0], 5U);  // every 5th scan fits
  EXPECT_GT(f.port.counters().scans_skipped_busy, 0U);
}

TEST(Rs232Port, StreamControlStopsAndRestarts) {
  Streaming f;
  EXPECT_TRUE(f.feed(encode_stream_control(false).value()).empty());
  EXPECT_TRUE(scan_numbers(f.run_for(200ms)).empty());
  (void)f.feed(encode_stream_control(true).value());
  EXPECT_EQ(scan_numbers(f.run_for(200ms)).size(), 5U);
}

TEST(Rs232Port, WrongPasswordIsRefusedAndChangesNothing) {
  Streaming f;
  (void)f.feed(encode_stream_control(false).value());
  const auto before = f.adapter.scanner().parameters();
  const CommandOptions wrong{.acknowledge = false, .password = make_password("WRONG")};
  auto frames = f.feed(encode_measurement_window(2, 0, 100, wrong).value());
  ASSERT_EQ(frames.size(), 1U);
  const auto a = PortFixture::decode(frames[0]);
  const auto* e = std::get_if<protocol::ErrorTelegram>(&a);
  ASSERT_NE(e, nullptr);  // 0x53: 0503 wrong password, parameter 0020, function 0005
  EXPECT_EQ(e->report, (protocol::ErrorReport{0x0503, 0x0020, 0x0005}));
  // Without a password at all, with acknowledge: 0x17 | opt | 20 | 05 03.
  frames =
      f.feed(encode_measurement_window(2, 0, 100, {.acknowledge = true, .password = {}}).value());
  ASSERT_EQ(frames.size(), 1U);
  const auto nak = std::get<Acknowledge>(PortFixture::decode(frames[0]));
  EXPECT_FALSE(nak.positive);
  EXPECT_EQ(nak.command, 0x20);
  EXPECT_EQ(nak.error, 0x0503);
  EXPECT_EQ(f.adapter.scanner().parameters(), before);
  EXPECT_EQ(f.port.counters().wrong_passwords, 2U);
}

TEST(Rs232Port, UserPasswordReplacesTheFactoryPassword) {
  PortFixture f;
  auto set = scanner::factory_default();
  set.passwords[0] = *make_password("SECRET1");
  ASSERT_TRUE(f.adapter.scanner().set_parameters(set, f.clock.now()));
  f.boot();
  f.port.attach(f.clock.now());
  (void)f.feed(encode_stream_control(false).value());
  const auto check = [&](std::string_view pw) {
    const auto frames = f.feed(
        encode_command(0x10, {}, {.acknowledge = true, .password = make_password(pw)}).value());
    return std::get<Acknowledge>(PortFixture::decode(frames.at(0))).positive;
  };
  EXPECT_FALSE(check("ROD4LE"));
  EXPECT_TRUE(check("SECRET1"));
}

TEST(Rs232Port, UnknownCommandIsAnsweredWithAnError) {
  Streaming f;
  (void)f.feed(encode_stream_control(false).value());
  auto frames = f.feed(encode_command(0x42, {}).value());
  ASSERT_EQ(frames.size(), 1U);
  EXPECT_EQ(std::get<protocol::ErrorTelegram>(PortFixture::decode(frames[0])).report,
            (protocol::ErrorReport{0x0501, 0x0042, 0x0005}));
  frames = f.feed(encode_command(0x42, {}, {.acknowledge = true, .password = {}}).value());
  EXPECT_EQ(std::get<Acknowledge>(PortFixture::decode(frames.at(0))).error, 0x0501);
  // Bad data: 0x19 with a rate code beyond the table, 0x22 with 2.
  frames = f.feed(encode_command(0x19, Bytes{0x00, 0x09}).value());
  EXPECT_EQ(std::get<protocol::ErrorTelegram>(PortFixture::decode(frames.at(0))).report.number,
            0x0504);
  EXPECT_EQ(f.port.line_settings().baud, 57600U);
}

// The same RS4 behind both paths ([RS4 manual §5.2.1], [RS4 manual §5.2.2] "(RS4 geht in
// Fehlerzustand)"): an unknown command over RS232 puts the RS4 into its error state, OSSD off,
// as over PROFIBUS; its one 0x53 is the RS4's own error event.
TEST(Rs232Port, UnknownCommandPutsTheRs4IntoItsErrorStateAsOverProfibus) {
  Streaming f;
  (void)f.feed(encode_stream_control(false).value());
  ASSERT_EQ(f.adapter.scanner().status().state, scanner::ScannerState::kMeasuring);
  const auto frames = f.feed(encode_command(0x42, {}).value());
  ASSERT_EQ(frames.size(), 1U);
  const auto e = std::get<protocol::ErrorTelegram>(PortFixture::decode(frames[0]));
  EXPECT_EQ(e.report, (protocol::ErrorReport{0x0501, 0x0042, 0x0005}));
  EXPECT_EQ(e.prefix.options.state, protocol::Option1State::kFault);
  EXPECT_EQ(f.adapter.scanner().status().state, scanner::ScannerState::kError);
  EXPECT_FALSE(f.adapter.scanner().ossd());
  EXPECT_EQ(f.adapter.error_memory().last_error().uc2_error, 0x0501);
  EXPECT_EQ(f.port.counters().error_telegrams, 0U) << "no second 0x53 beside the event";
  EXPECT_EQ(f.port.counters().events, 1U);
}

// One RS4 behind both paths [docs/decisions.md#rs4-one-command-set]: a malformed command (option
// bytes that do not decode, data after a command that takes none) is answered alike over
// PROFIBUS and RS232, 0x53 with 0x0504 (bad data), the command byte and function 0x0005; the RS4
// keeps measuring on both. Until this change PROFIBUS took each of them for an unknown command
// (0x0501) and put the RS4 into its error state.
TEST(Rs232Port, MalformedCommandsAreAnsweredAlikeOverProfibusAndRs232) {
  const std::vector<Bytes> bodies{
      {0x14, 0x00},        // OPT1 announces 0 option bytes
      {0x14, 0x01, 0x00},  // COM_CMD_ALIVE with a data byte
      {0x24, 0x01, 0x07},  // request one scan with a data byte
      {0x42, 0x81},        // an unknown code whose OPT1 has the reserved bit 7 set
  };
  Streaming f;
  (void)f.feed(encode_stream_control(false).value());
  adapter::testing::Rig rig;
  rig.start();
  rig.run(31s);
  for (const auto& body : bodies) {
    const auto frames = f.feed(protocol::frame_rs232(body).value());
    ASSERT_EQ(frames.size(), 1U) << int{body[0]};
    const auto rs232 = std::get<protocol::ErrorTelegram>(PortFixture::decode(frames[0]));
    rig.write(adapter::testing::Rig::block(body));
    const auto answer = rig.read_answer();
    const auto profibus = protocol::decode_telegram(answer);
    ASSERT_TRUE(profibus) << int{body[0]};
    const auto& e = std::get<protocol::ErrorTelegram>(profibus.value());
    const protocol::ErrorReport expected{0x0504, body[0], 0x0005};
    EXPECT_EQ(rs232.report, expected) << int{body[0]};
    EXPECT_EQ(e.report, expected) << int{body[0]};
  }
  EXPECT_EQ(f.adapter.scanner().status().state, scanner::ScannerState::kMeasuring);
  EXPECT_EQ(rig.adapter.scanner().status().state, scanner::ScannerState::kMeasuring);
}

TEST(Rs232Port, MalformedFramesGetSilenceAndNeverDisturbTheNext) {
  Streaming f;
  (void)f.feed(encode_stream_control(false).value());
  const Bytes alive{0x00, 0x00, 0x14, 0x01, 0x15, 0x00, 0x00, 0x00};
  // bad check byte (16 instead of 15) → silence
  EXPECT_TRUE(f.feed({0x00, 0x00, 0x14, 0x01, 0x16, 0x00, 0x00, 0x00}).empty());
  EXPECT_EQ(f.feed(alive).size(), 1U);
  // missing end marker: 14 01 15 00 00 then the next start: the cut frame is dropped
  auto frames =
      f.feed({0x00, 0x00, 0x14, 0x01, 0x15, 0x00, 0x00, 0x14, 0x01, 0x15, 0x00, 0x00, 0x00});
  EXPECT_EQ(frames.size(), 1U);  // only the second alive
  // stuffing violation inside a body (00 00 07) → the cut frame is dropped, 07... resyncs
  EXPECT_TRUE(f.feed({0x00, 0x00, 0x24, 0x01, 0x00, 0x00, 0x07, 0x00, 0x00, 0x00}).empty());
  EXPECT_EQ(f.feed(alive).size(), 1U);
  // oversized (3000 body bytes > max_body 2048) → silence, then the next is answered
  Bytes big{0x00, 0x00, 0x63, 0x01};
  big.insert(big.end(), 3000, 0x55);
  big.insert(big.end(), {0x77, 0x00, 0x00, 0x00});
  EXPECT_TRUE(f.feed(big).empty());
  EXPECT_EQ(f.feed(alive).size(), 1U);
  // 5: the violation's 07 opened a frame that the end mark closed too short.
  EXPECT_EQ(f.port.counters().framing_errors, 5U);
  // split across calls byte by byte: still one answer
  std::size_t answers = 0;
  for (const auto b : alive) answers += f.feed(Bytes{b}).size();
  EXPECT_EQ(answers, 1U);
}

TEST(Rs232Port, DetachedPortIsSilent) {
  PortFixture f;
  f.boot();
  EXPECT_TRUE(f.feed({0x00, 0x00, 0x14, 0x01, 0x15, 0x00, 0x00, 0x00}).empty());
  EXPECT_TRUE(f.run_for(200ms).empty());
  EXPECT_EQ(f.port.counters().ignored_while_detached, 8U);
  f.port.attach(f.clock.now());
  EXPECT_FALSE(f.run_for(200ms).empty());
  f.port.detach(f.clock.now());
  EXPECT_TRUE(f.feed({0x00, 0x00, 0x14, 0x01, 0x15, 0x00, 0x00, 0x00}).empty());
  EXPECT_TRUE(f.run_for(200ms).empty());
  EXPECT_FALSE(f.port.next_deadline().has_value());
}

TEST(Rs232Port, WarningsOfTheRs4AreSentAsTheyOccur) {
  Streaming f;
  (void)f.feed(encode_stream_control(false).value());
  f.adapter.scanner().set_contamination(60, f.clock.now());  // ≥ 50 %: window warning
  const auto frames = f.run_for(100ms);
  ASSERT_FALSE(frames.empty());
  const auto a = PortFixture::decode(frames.front());
  EXPECT_TRUE(std::holds_alternative<protocol::WarningTelegram>(a));
  EXPECT_EQ(f.port.counters().events, 1U);
}

TEST(Rs232Port, OptionsValidate) {
  EXPECT_FALSE(PortOptions{}.validate());
  PortOptions o;
  o.baud = 1234;
  ASSERT_TRUE(o.validate());
  EXPECT_NE(o.validate()->find("1234"), std::string::npos);
  o = PortOptions{};
  o.max_body = 100;
  EXPECT_TRUE(o.validate());
}

}  // namespace
}  // namespace rs4sim::rs4::rs232::testing
