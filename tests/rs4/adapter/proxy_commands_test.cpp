// The proxy's commands on the device side, byte by byte ([docs/proxy-protocol.md]): adapter
// commands 0x98/0x99 and the RS4 transfer commands 0x60..0x65, WRITE then READ through the
// block protocol ([RS4 manual §5.2.1]). Expected bytes are written from the contract, one
// field per line. The factory set's transfer CRC-32 (9C C1 9E 11) was computed from the layout
// in docs/rs4-scanner.md by a separate script and is cross-checked against the codec; so
// were the chunk CRCs (last chunk of the factory set F6 DF 90 59, chunk 0 of the factory set
// with response steps 2: B2 69 44 AF).
#include "proxy_rig.h"
#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

using dp::slave::AcyclicChannel;
using protocol::TransferStatus;

Bytes data_of(const dp::slave::AcyclicResult& r) { return Bytes(r.data.begin(), r.data.end()); }

struct ProxyCommands : ::testing::Test {
  Rig rig;
  void SetUp() override { boot_with_proxy(rig); }
  void begin_sync() { ASSERT_EQ(command(rig, {0x98}), (Bytes{0x98, 0x01, 0x03, 0x01})); }
  // A sync with a whole download of the RS4's set with `steps` committed, then a second
  // download opened (and left open).
  void sync_with_committed_download(std::uint8_t steps) {
    begin_sync();
    auto set = rig.adapter.scanner().parameters();
    set.response_steps = steps;
    const auto blob = scanner::encode_for_transfer(set);
    ASSERT_EQ(download(rig, blob, scanner::crc32_iso_hdlc(blob)).status, TransferStatus::kOk);
    ASSERT_FALSE(rig.adapter.scanner().factory_settings());
    ASSERT_EQ(transfer(rig, protocol::DownloadBeginRequest{8507, 0}).status, TransferStatus::kOk);
  }
};

TEST(ProxyCommandsBeforeBoot, BeginWithoutRequestStartsNothingAndTransferIsRefused) {
  Rig rig;
  rig.start();  // RS4 still booting: no Proxy-Request
  EXPECT_EQ(command(rig, {0x98}), (Bytes{
                                      0x98,  // PROFI_CMD_PROXY_BEGIN
                                      0x00,  // reason: none (nothing requested)
                                      0x00,  // direction: none
                                      0x01,  // flags bit 0: factory setting
                                  }));
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kWaitRs4);
  EXPECT_EQ(command(rig, {0x60, 0x01}), (Bytes{
                                            0x60,  // IDENTIFY
                                            0x05,  // option 1: 1 byte, state 001 initialisation
                                            0x07,  // status 7: RS4 not operational
                                        }));
}

TEST_F(ProxyCommands, IdentifyOfTheFactoryDevice) {
  ASSERT_EQ(scanner::transfer_checksum(scanner::factory_default()), 0x9CC19E11U);
  EXPECT_EQ(command(rig, {0x60, 0x01}), (Bytes{
                                            0x60,  // IDENTIFY
                                            0x0B,  // option 1: 3 bytes, state 010 measuring
                                            0x90,  // option 2: restart interlock, option 3 follows
                                            0x81,  // option 3: field pair 1
                                            0x00,  // status ok
                                            0x00, 0x04,              // device type 4
                                            0x00, 0x01, 0x23, 0x45,  // serial number 0x12345
                                            0x01, 0x00,              // firmware 1.0
                                            0x01,                    // set format version 1
                                            0x21, 0x3B,              // set size 8507
                                            0x04, 0x00,              // chunk size 1024
                                            0x9C, 0xC1, 0x9E, 0x11,  // set CRC-32 (transfer form)
                                            0x01,                    // flags: factory default
                                            0x00, 0x00,              // change counter 0
                                        }));
}

TEST_F(ProxyCommands, ProxyBeginAfterBootAsksForADownloadAndShowsProxyBusy) {
  EXPECT_EQ(data_of(rig.read()), (Bytes{0x41, 0x04, 0xFF, 0xFF}));  // flow 100 normal
  EXPECT_EQ(command(rig, {0x98}), (Bytes{
                                      0x98,  // PROFI_CMD_PROXY_BEGIN
                                      0x01,  // reason: power-up
                                      0x03,  // direction: download (the RS4 holds factory settings)
                                      0x01,  // flags: factory setting
                                  }));
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kSyncRunning);
  rig.run(40ms);
  EXPECT_FALSE(rig.host_input() & kInputProxyRequest);  // [RS4 manual §5.1.1] bit 2 reset
  // [RS4 manual §5.2.1] table 5.2-2: 011 "proxy busy" on both channels.
  EXPECT_EQ(data_of(rig.read()), (Bytes{0x31, 0x04, 0xFF, 0xFF}));
  EXPECT_EQ(rig.adapter.flow_byte(AcyclicChannel::kC2, false), 0x31);
  // A second BEGIN during the sync starts nothing new.
  EXPECT_EQ(command(rig, {0x98}), (Bytes{0x98, 0x00, 0x00, 0x01}));
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kSyncRunning);
}

TEST_F(ProxyCommands, LastUploadChunk) {
  const auto a = command(rig, {0x61, 0x01, 0x08});  // UPLOAD_CHUNK 8
  ASSERT_EQ(a.size(), 4U + 1 + 8 + 315);
  EXPECT_EQ(Bytes(a.begin(), a.begin() + 13), (Bytes{
                                                  0x61,                    // UPLOAD_CHUNK
                                                  0x0B, 0x90, 0x81,        // option bytes
                                                  0x00,                    // status ok
                                                  0x08,                    // chunk 8
                                                  0x09,                    // of 9
                                                  0x01, 0x3B,              // 315 bytes
                                                  0xF6, 0xDF, 0x90, 0x59,  // their CRC-32
                                              }));
  const auto blob = scanner::encode_for_transfer(rig.adapter.scanner().parameters());
  EXPECT_EQ(Bytes(a.begin() + 13, a.end()), Bytes(blob.begin() + 8192, blob.end()));
  EXPECT_EQ(command(rig, {0x61, 0x01, 0x09}), (Bytes{0x61, 0x0B, 0x90, 0x81, 0x02}));  // bad chunk
}

// Outside a sync a download needs the password, as on RS232 (docs/rs232.md "Reactions", the
// one command set [docs/decisions.md#rs4-one-command-set]); without it the RS4 answers 0x53
// 0503. With the password it is a user's parametrisation (tests/rs4/adapter/command_set_test).
TEST_F(ProxyCommands, DownloadOutsideASyncIsRefused) {
  EXPECT_EQ(command(rig, {0x62, 0x01, 0x21, 0x3B, 0x9C, 0xC1, 0x9E, 0x11}),
            (Bytes{
                0x53,              // COM_CMD_ERROR_OCCURE
                0x0B, 0x90, 0x81,  // option bytes
                0x05, 0x03,        // error 0x0503: wrong password
                0x00, 0x62,        // parameter: the command
                0x00, 0x05,        // function: the command interpreter
            }));
  EXPECT_EQ(command(rig, {0x64, 0x01}),
            (Bytes{0x53, 0x0B, 0x90, 0x81, 0x05, 0x03, 0x00, 0x64, 0x00, 0x05}));
  EXPECT_EQ(command(rig, {0x65, 0x01}),
            (Bytes{0x53, 0x0B, 0x90, 0x81, 0x05, 0x03, 0x00, 0x65, 0x00, 0x05}));
  EXPECT_FALSE(rig.adapter.proxy_session().download_open());
}

TEST_F(ProxyCommands, DownloadBeginAndItsRefusals) {
  begin_sync();
  EXPECT_EQ(command(rig, {0x63, 0x01, 0x00, 0xAA}), (Bytes{0x63, 0x0B, 0x90, 0x81, 0x03}));
  EXPECT_EQ(command(rig, {0x64, 0x01}), (Bytes{0x64, 0x0B, 0x90, 0x81, 0x03}));  // no download
  EXPECT_EQ(command(rig, {0x62, 0x01, 0x21, 0x3A, 0x00, 0x00, 0x00, 0x00}),
            (Bytes{0x62, 0x0B, 0x90, 0x81, 0x04}));  // size 8506: size mismatch
  EXPECT_EQ(command(rig, {0x62, 0x01, 0x21, 0x3B, 0x9C, 0xC1, 0x9E}),
            (Bytes{0x62, 0x0B, 0x90, 0x81, 0x01}));  // one byte short: wrong length
  EXPECT_EQ(command(rig, {0x62, 0x01, 0x21, 0x3B, 0x9C, 0xC1, 0x9E, 0x11}),
            (Bytes{
                0x62,  // DOWNLOAD_BEGIN
                0x0D,  // option 1: state 011 configuration ([RS4 manual §5.2.3]), no option 2:
                       // the RS4 is in its configuration mode from here ([RS4 manual §7.1.2])
                0x00,        // status ok
                0x09,        // 9 chunks
                0x04, 0x00,  // of 1024 bytes
            }));
  // Chunk 1 before chunk 0: bad chunk; a short chunk 0: size mismatch.
  EXPECT_EQ(command(rig, {0x63, 0x01, 0x01, 0xAA}), (Bytes{0x63, 0x0D, 0x02}));
  EXPECT_EQ(command(rig, {0x63, 0x01, 0x00, 0xAA}), (Bytes{0x63, 0x0D, 0x04}));
  // IDENTIFY flags (byte 20 behind the single option byte): factory, download open.
  EXPECT_EQ(command(rig, {0x60, 0x01}).at(20), 0x03);
}

TEST_F(ProxyCommands, ChunkEchoAndCommit) {
  begin_sync();
  auto set = rig.adapter.scanner().parameters();
  set.response_steps = 2;
  const auto blob = scanner::encode_for_transfer(set);
  const auto crc = scanner::crc32_iso_hdlc(blob);
  ASSERT_EQ(transfer(rig, protocol::DownloadBeginRequest{8507, crc}).status, TransferStatus::kOk);
  Bytes chunk0{0x63, 0x01, 0x00};
  chunk0.insert(chunk0.end(), blob.begin(), blob.begin() + 1024);
  EXPECT_EQ(command(rig, chunk0), (Bytes{
                                      0x63,                    // DOWNLOAD_CHUNK
                                      0x0D,                    // option 1: configuration
                                      0x00,                    // status ok
                                      0x00,                    // chunk 0
                                      0xB2, 0x69, 0x44, 0xAF,  // echo: CRC-32 of what arrived
                                  }));
  for (std::uint8_t x = 1; x < 9; ++x) {
    const auto off = std::size_t{x} * 1024;
    const auto a = transfer(rig, protocol::DownloadChunkRequest{
                                     x, std::span<const std::uint8_t>(blob).subspan(
                                            off, std::min<std::size_t>(1024, blob.size() - off))});
    ASSERT_EQ(a.status, TransferStatus::kOk);
  }
  const auto commit = command(rig, {0x64, 0x01});
  ASSERT_EQ(commit.size(), 9U);
  EXPECT_EQ(commit[0], 0x64);
  EXPECT_EQ(commit[4], 0x00);  // status ok
  EXPECT_EQ(Bytes(commit.begin() + 5, commit.end()),
            (Bytes{static_cast<std::uint8_t>(crc >> 24), static_cast<std::uint8_t>(crc >> 16),
                   static_cast<std::uint8_t>(crc >> 8), static_cast<std::uint8_t>(crc)}));
  EXPECT_EQ(rig.adapter.scanner().parameters().response_steps, 2);
  EXPECT_EQ(rig.adapter.scanner().change_counter(), 1);
}

TEST_F(ProxyCommands, ProxyEndOkReleasesTheOssd) {
  EXPECT_EQ(command(rig, {0x99, 0x00, 0x00, 0x00}), (Bytes{
                                                        0x99,  // PROFI_CMD_PROXY_END
                                                        0x00,  // not accepted: no sync running
                                                        0x01,  // flags: factory setting
                                                    }));
  begin_sync();
  rig.restart_pulse();
  EXPECT_FALSE(rig.ossd());  // Proxy-Enable 1: not before END
  EXPECT_EQ(command(rig, {0x99, 0x00, 0x00, 0x00}), (Bytes{0x99, 0x01, 0x01}));
  rig.run(40ms);
  EXPECT_TRUE(rig.ossd());
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kDone);
  EXPECT_EQ(data_of(rig.read()), (Bytes{0x41, 0x04, 0xFF, 0xFF}));  // flow 100 again
}

TEST_F(ProxyCommands, ProxyEndFailedResetsToFactoryAndRequestsARetry) {
  sync_with_committed_download(5);
  const auto alarms = rig.control.alarms.size();
  EXPECT_EQ(command(rig, {0x99, 0x01, 0x2B, 0x09}), (Bytes{
                                                        0x99,  // PROFI_CMD_PROXY_END
                                                        0x01,  // accepted
                                                        0x01,  // flags: factory setting now
                                                    }));
  EXPECT_TRUE(rig.adapter.scanner().factory_settings());
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2B09);
  EXPECT_EQ(rig.control.alarms.size(), alarms + 1);  // diagnosis alarm "coming"
  rig.run(40ms);
  EXPECT_TRUE(rig.host_input() & kInputProxyRequest);
  EXPECT_EQ(command(rig, {0x98}), (Bytes{
                                      0x98,  // PROFI_CMD_PROXY_BEGIN
                                      0x03,  // reason: retry
                                      0x03,  // direction: download
                                      0x01,  // flags: factory setting
                                  }));
}

TEST_F(ProxyCommands, BreakRollsBackToFactorySettings) {
  sync_with_committed_download(1);
  const auto a = command(rig, {0x65, 0x01});
  ASSERT_EQ(a.size(), 6U);
  EXPECT_EQ(a[0], 0x65);  // DOWNLOAD_BREAK
  EXPECT_EQ(a[4], 0x00);  // status ok
  EXPECT_EQ(a[5], 0x01);  // flags: factory setting
  EXPECT_TRUE(rig.adapter.scanner().factory_settings());
  EXPECT_EQ(command(rig, {0x65, 0x01}).at(4), 0x03);  // nothing open any more
}

TEST_F(ProxyCommands, UserCommandDuringASyncAbortsIt) {
  begin_sync();
  const auto alarms = rig.control.alarms.size();
  EXPECT_EQ(command(rig, {0x90}).at(0), 0x90);  // the user's command is still served
  ASSERT_EQ(rig.control.alarms.size(), alarms + 1);
  EXPECT_EQ(rig.control.alarms.back().type, protocol::kAlarmTypeDiagnosis);
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kRequested);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc1_error, 0x2B01);
  EXPECT_EQ(rig.adapter.proxy_session().reason(), protocol::SyncReason::kRetry);
  EXPECT_EQ(command(rig, {0x99, 0x00, 0x00, 0x00}), (Bytes{0x99, 0x00, 0x01}));  // too late
}

TEST_F(ProxyCommands, Class2ReadDuringASyncAbortsIt) {
  begin_sync();
  (void)rig.read(240, AcyclicChannel::kC2);
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kRequested);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2B01);
}

// [docs/decisions.md#rs4-class2-adapter-commands]: the adapter refuses a class 2 master's 98 and
// 99 with 93 01 code (table 5.2-3); nothing starts or ends, the RS4 sees nothing.
TEST_F(ProxyCommands, ProxyCommandsAreClass1Only) {
  EXPECT_EQ(command(rig, {0x98}, AcyclicChannel::kC2), (Bytes{0x93, 0x01, 0x98}));
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kRequested);
  EXPECT_EQ(command(rig, {0x99, 0x00, 0x00, 0x00}, AcyclicChannel::kC2),
            (Bytes{0x93, 0x01, 0x99}));
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kRequested);
  EXPECT_EQ(rig.adapter.counters().rs4_commands, 0u);
}

TEST_F(ProxyCommands, LinkLossDuringADownloadResetsToFactorySettings) {
  sync_with_committed_download(3);
  rig.adapter.on_state_change(dp::slave::State::kDataExch, dp::slave::State::kWaitPrm,
                              dp::slave::TransitionReason::kWatchdog, rig.now);
  EXPECT_TRUE(rig.adapter.scanner().factory_settings());
  EXPECT_FALSE(rig.adapter.proxy_session().download_open());
  EXPECT_EQ(rig.adapter.proxy_phase(), ProxyPhase::kRequested);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
