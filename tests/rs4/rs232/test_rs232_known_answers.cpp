// The worked examples of the RS4's RS232 framing ([roboticslibrary/rl LeuzeRs4.cpp], docs/rs232.md)
// on the live interface: bytes into the port, bytes out of it, on the manual clock.
#include "rs232_fixture.h"
#include "rs4/rs232/rs232_client.h"
#include "rs4/scanner/parameter_set.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::rs232::testing {
namespace {

// The scanner of the measurement example: automatic restart (no interlock flag), a tiny
// protective field where the scene is empty (no violation flags), window resolution 4, segments
// 0..8, and a raw contour with 1000 mm at segment 0, 0 mm at 4 and 256 mm at 8.
void example_scene(PortFixture& f) {
  auto set = scanner::factory_default();
  set.restart_mode = scanner::RestartMode::kAutomatic;
  for (auto& pair : set.pairs) pair = scanner::FieldPair{};
  set.pairs[0].protective_mm[500] = 100;  // a start field is required; nothing is there
  set.measurement = scanner::MeasurementOutput{4, 0, 8};
  ASSERT_TRUE(f.adapter.scanner().set_parameters(set, f.clock.now()));
  scanner::RawContour raw;
  raw.mm.assign(scanner::kSegmentCount, scanner::kNoEchoMm);
  raw.mm[0] = 1000;
  raw.mm[4] = 0;
  raw.mm[8] = 256;
  ASSERT_TRUE(f.adapter.scanner().edit_scene(f.clock.now()).add(raw));
}

// The example scene, booted, the PC adapter attached and the stream switched off
// (22 01 00: no acknowledge asked, so no answer).
void open_quiet_example(PortFixture& f) {
  example_scene(f);
  f.boot();
  f.port.attach(f.clock.now());
  (void)f.feed({0x00, 0x00, 0x22, 0x01, 0x00, 0x23, 0x00, 0x00, 0x00});
}

TEST(Rs232KnownAnswers, FirstStreamedScanIsTheMeasurementExample) {
  PortFixture f;
  example_scene(f);
  f.adapter.power_on(f.clock.now());
  f.port.attach(f.clock.now());  // attached at start-up: the port opens while the RS4 boots
  const auto frames = f.run_for(100ms);
  ASSERT_FALSE(frames.empty());
  // 00 00 | 23 | 0B 80 81 (3 options, measuring; option 2 only as marker; pair 1)
  // | scan 1: 00 FE 00 FE 00 FE 01 FE | step 04 | start 00 00 FF(stuffed) 00 | stop 08
  // | 1000 = 03 E8 | 0 = 00 00 FF(stuffed) | 256 = 01 00 | CHK CE | 00 00 00
  const Bytes expected{0x00, 0x00, 0x23, 0x0B, 0x80, 0x81, 0x00, 0xFE, 0x00, 0xFE, 0x00,
                       0xFE, 0x01, 0xFE, 0x04, 0x00, 0x00, 0xFF, 0x00, 0x08, 0x03, 0xE8,
                       0x00, 0x00, 0xFF, 0x01, 0x00, 0xCE, 0x00, 0x00, 0x00};
  EXPECT_EQ(frames.front(), expected);
}

TEST(Rs232KnownAnswers, AliveIsAnsweredWithTheDevicesOptions) {
  PortFixture f;
  open_quiet_example(f);
  // alive, no ack: 00 00 | 14 | 01 | CHK 15 | 00 00 00
  const auto frames = f.feed({0x00, 0x00, 0x14, 0x01, 0x15, 0x00, 0x00, 0x00});
  ASSERT_EQ(frames.size(), 1U);
  // 14 | 0B 80 81 | CHK 14^0B^80^81 = 1E
  EXPECT_EQ(frames[0], (Bytes{0x00, 0x00, 0x14, 0x0B, 0x80, 0x81, 0x1E, 0x00, 0x00, 0x00}));
}

TEST(Rs232KnownAnswers, RequestOneScan) {
  PortFixture f;
  open_quiet_example(f);
  // request one scan: 00 00 | 24 | 01 | CHK 25 | 00 00 00
  const auto frames = f.feed({0x00, 0x00, 0x24, 0x01, 0x25, 0x00, 0x00, 0x00});
  ASSERT_EQ(frames.size(), 1U);
  const auto answer = PortFixture::decode(frames[0]);
  const auto* m = std::get_if<protocol::MeasurementTelegram>(&answer);
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->values, (std::vector<std::uint16_t>{1000, 0, 256}));
  EXPECT_EQ(m->resolution, 4);
  EXPECT_EQ(m->stop, 8);
}

TEST(Rs232KnownAnswers, SetBaudAcknowledgedAtTheOldRateThenSwitches) {
  PortFixture f;
  f.boot();
  f.port.attach(f.clock.now());
  (void)f.feed({0x00, 0x00, 0x22, 0x01, 0x00, 0x23, 0x00, 0x00, 0x00});  // stream off
  EXPECT_EQ(f.port.line_settings().baud, 57600U);
  // set baud 4800 with acknowledge: 00 00 | 19 | 41 | 00 00 FF(stuffed) | CHK A7 | 00 00 00
  const auto frames = f.feed({0x00, 0x00, 0x19, 0x41, 0x00, 0x00, 0xFF, 0xA7, 0x00, 0x00, 0x00});
  ASSERT_EQ(frames.size(), 1U);
  const auto answer = PortFixture::decode(frames[0]);
  const auto* ack = std::get_if<Acknowledge>(&answer);
  ASSERT_NE(ack, nullptr);
  EXPECT_TRUE(ack->positive);
  EXPECT_EQ(ack->command, 0x19);
  // Still 57 600 while the acknowledgement is on the line (its frame time at 57 600 baud).
  EXPECT_EQ(f.port.line_settings().baud, 57600U);
  ASSERT_TRUE(f.port.next_deadline().has_value());
  const auto ack_time =
      stream::character_time(line_8n1(57600), static_cast<double>(frames[0].size()));
  EXPECT_EQ(*f.port.next_deadline(), f.clock.now() + ack_time);
  (void)f.run_for(ack_time);
  EXPECT_EQ(f.port.line_settings(), line_8n1(4800));
  EXPECT_EQ(f.port.counters().baud_changes, 1U);
}

TEST(Rs232KnownAnswers, PasswordFrameIsAcceptedInTheFactoryState) {
  PortFixture f;
  f.boot();
  f.port.attach(f.clock.now());
  (void)f.feed({0x00, 0x00, 0x22, 0x01, 0x00, 0x23, 0x00, 0x00, 0x00});  // stream off
  // 00 00 | 10 | 21 (password follows) | "ROD4LE" FF FF | CHK 55 | 00 00 00: no ack asked → silent
  EXPECT_TRUE(f.feed({0x00, 0x00, 0x10, 0x21, 0x52, 0x4F, 0x44, 0x34, 0x4C, 0x45, 0xFF, 0xFF, 0x55,
                      0x00, 0x00, 0x00})
                  .empty());
  EXPECT_EQ(f.port.counters().wrong_passwords, 0U);
}

TEST(Rs232KnownAnswers, ClientEncodesTheWorkedExamples) {
  EXPECT_EQ(encode_command(0x14, {}).value(),
            (Bytes{0x00, 0x00, 0x14, 0x01, 0x15, 0x00, 0x00, 0x00}));
  EXPECT_EQ(encode_set_baud(4800, {.acknowledge = true, .password = std::nullopt}).value(),
            (Bytes{0x00, 0x00, 0x19, 0x41, 0x00, 0x00, 0xFF, 0xA7, 0x00, 0x00, 0x00}));
  EXPECT_EQ(
      encode_command(0x10, {}, {.acknowledge = false, .password = make_password("ROD4LE")}).value(),
      (Bytes{0x00, 0x00, 0x10, 0x21, 0x52, 0x4F, 0x44, 0x34, 0x4C, 0x45, 0xFF, 0xFF, 0x55, 0x00,
             0x00, 0x00}));
  EXPECT_EQ(encode_command(0x24, {}).value(),
            (Bytes{0x00, 0x00, 0x24, 0x01, 0x25, 0x00, 0x00, 0x00}));
  EXPECT_FALSE(make_password("TOOLONGPW"));
  EXPECT_FALSE(encode_set_baud(1234));
}

// The annotated frames of docs/rs232.md "Parameter set over RS232".
TEST(Rs232KnownAnswers, DocumentedTransferFrames) {
  const CommandOptions pw{.acknowledge = false, .password = make_password("ROD4LE")};
  EXPECT_EQ(encode_transfer(protocol::IdentifyRequest{}).value(),
            (Bytes{0x00, 0x00, 0x60, 0x01, 0x61, 0x00, 0x00, 0x00}));
  EXPECT_EQ(encode_transfer(protocol::UploadChunkRequest{0}).value(),
            (Bytes{0x00, 0x00, 0x61, 0x01, 0x00, 0x60, 0x00, 0x00, 0x00}));
  EXPECT_EQ(encode_transfer(protocol::DownloadBeginRequest{8507, 0x12345678}, pw).value(),
            (Bytes{0x00, 0x00, 0x62, 0x21, 0x52, 0x4F, 0x44, 0x34, 0x4C, 0x45, 0xFF,
                   0xFF, 0x21, 0x3B, 0x12, 0x34, 0x56, 0x78, 0x35, 0x00, 0x00, 0x00}));
  EXPECT_EQ(encode_transfer(protocol::DownloadCommitRequest{}, pw).value(),
            (Bytes{0x00, 0x00, 0x64, 0x21, 0x52, 0x4F, 0x44, 0x34, 0x4C, 0x45, 0xFF, 0xFF, 0x21,
                   0x00, 0x00, 0x00}));
  EXPECT_EQ(
      encode_measurement_window(4, 0, 528, {.acknowledge = true, .password = pw.password}).value(),
      (Bytes{0x00, 0x00, 0x20, 0x61, 0x52, 0x4F, 0x44, 0x34, 0x4C, 0x45, 0xFF,
             0xFF, 0x04, 0x00, 0x00, 0xFF, 0x02, 0x10, 0xCC, 0x00, 0x00, 0x00}));
  // The PROFIBUS form of the same request is the unframed body with option 1 = 01.
  EXPECT_EQ(protocol::encode_request(protocol::UploadChunkRequest{0}).value(),
            (Bytes{0x61, 0x01, 0x00}));
}

// The device's answers of docs/rs232.md "Reactions" (options 0B 80 81 of the example scene).
TEST(Rs232KnownAnswers, DocumentedReactions) {
  PortFixture f;
  open_quiet_example(f);
  const CommandOptions no_pw_ack{.acknowledge = true, .password = std::nullopt};
  EXPECT_EQ(
      f.feed(encode_set_baud(57600, no_pw_ack).value()),
      (std::vector<Bytes>{{0x00, 0x00, 0x16, 0x0B, 0x80, 0x81, 0x19, 0x05, 0x00, 0x00, 0x00}}));
  EXPECT_EQ(f.feed(encode_measurement_window(4, 0, 528, no_pw_ack).value()),
            (std::vector<Bytes>{
                {0x00, 0x00, 0x17, 0x0B, 0x80, 0x81, 0x20, 0x05, 0x03, 0x3B, 0x00, 0x00, 0x00}}));
  EXPECT_EQ(f.feed(encode_measurement_window(4, 0, 528, {}).value()),
            (std::vector<Bytes>{{0x00, 0x00, 0x53, 0x0B, 0x80, 0x81, 0x05, 0x03, 0x00, 0x20, 0x00,
                                 0x05, 0x7A, 0x00, 0x00, 0x00}}));
}

}  // namespace
}  // namespace rs4sim::rs4::rs232::testing
