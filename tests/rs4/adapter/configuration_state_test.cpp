// The RS4's configuration state during a download over PROFIBUS ([RS4 manual §7.1.2]
// "schaltet das OSSD-Signal während eines Downloads … aus"; [RS4 manual §5.1.1] bit 4 "RS4-
// Parametrierzustand"; [RS4 manual §5.2.3] option 1 bits 2..4): the download is not applied in
// one call. DOWNLOAD_BEGIN puts the RS4 into configuration when the RS4 executes it (the command
// time after its WRITE, [RS4 manual §5.2.1]); from then on option 1 reads 011 and bit 4 reads 1
// at once, the OSSD bit follows the RS4's OSSDs 10 ms later ([RS4 manual §6.6]); the commit, a
// refused commit and the end of the sync leave it. Both sides of each bound on the manual clock.
#include "proxy_rig.h"
#include "rs4/protocol/adapter_answer.h"
#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

using scanner::ScannerState;

// Option 1 bits 2..4 of an answer body (CMD, OPT1, …) as the wire carries them.
std::uint8_t option1_state_bits(const Bytes& answer) {
  return answer.size() > 1 ? static_cast<std::uint8_t>((answer[1] >> 2) & 0x07) : 0xFF;
}

// Proxy-Enable 0 (the OSSD bit is released without the proxy, [RS4 manual §5.1.2]), so the
// OSSD bit is 1 before the download and the moment it drops is visible; Proxy-Request is set
// from the power-up, so PROFI_CMD_PROXY_BEGIN starts a sync (factory settings: a download).
struct Configuring : ::testing::Test {
  Rig rig;
  Bytes blob;
  std::uint32_t crc = 0;
  void SetUp() override {
    ASSERT_TRUE(rig.boot_and_release());
    const auto begin = protocol::decode_proxy_begin_answer(command(rig, {0x98}));
    ASSERT_TRUE(begin);
    ASSERT_EQ(begin.value().direction, protocol::SyncDirection::kDownload);
    auto set = scanner::factory_default();
    set.response_steps = 3;
    blob = scanner::encode_for_transfer(set);
    crc = scanner::crc32_iso_hdlc(blob);
  }
  [[nodiscard]] std::uint8_t in() const { return rig.adapter.input_byte(); }
  [[nodiscard]] ScannerState state() const { return rig.adapter.scanner().status().state; }
  void send_chunks() {
    for (std::size_t x = 0; x * protocol::kMaxChunkSize < blob.size(); ++x) {
      const std::size_t off = x * protocol::kMaxChunkSize;
      const std::size_t n = std::min(protocol::kMaxChunkSize, blob.size() - off);
      const auto a = command(
          rig, request(protocol::DownloadChunkRequest{
                   static_cast<std::uint8_t>(x),
                   std::span<const std::uint8_t>(blob).subspan(off, n)}));
      ASSERT_EQ(option1_state_bits(a), 0b011) << "chunk " << x << ": still in configuration";
      ASSERT_EQ(in() & (kInputOperatingState | kInputOssd), kInputOperatingState) << x;
    }
  }
};

TEST_F(Configuring, DownloadBeginSwitchesTheRs4IntoConfigurationWhenItExecutes) {
  ASSERT_EQ(in() & (kInputOssd | kInputOperatingState), kInputOssd) << "protecting, OSSD 1";
  rig.write(Rig::block(
      request(protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()), crc})));
  const auto written = rig.now;
  rig.advance(39ms);
  EXPECT_EQ(state(), ScannerState::kMeasuring) << "39 ms: the RS4 still works on it";
  EXPECT_EQ(in() & (kInputOssd | kInputOperatingState), kInputOssd);
  rig.advance(1ms);
  EXPECT_EQ(rig.now - written, 40ms);
  EXPECT_EQ(state(), ScannerState::kConfiguration) << "40 ms: DOWNLOAD_BEGIN executed";
  EXPECT_FALSE(rig.adapter.scanner().ossd()) << "the RS4's OSSDs go off with the download";
  EXPECT_NE(in() & kInputOperatingState, 0) << "bit 4 at once: RS4-Parametrierzustand";
  EXPECT_NE(in() & kInputOssd, 0) << "the OSSD bit follows 10 ms later";
  rig.advance(9ms);
  EXPECT_NE(in() & kInputOssd, 0) << "49 ms";
  rig.advance(1ms);
  EXPECT_EQ(in() & kInputOssd, 0) << "50 ms: the OSSD bit is 0 at the download's start";
  const auto answer = rig.read_answer();
  ASSERT_FALSE(answer.empty());
  EXPECT_EQ(answer[0], 0x62);
  EXPECT_EQ(option1_state_bits(answer), 0b011) << "option 1: configuration";
  const auto decoded = protocol::decode_answer(answer);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded.value().status, protocol::TransferStatus::kOk);
  EXPECT_EQ(decoded.value().options.state, protocol::Option1State::kConfiguration);
}

TEST_F(Configuring, CommitLeavesConfigurationWithTheNewSetAndTheStartInterlock) {
  ASSERT_EQ(transfer(rig, protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()),
                                                         crc})
                .status,
            protocol::TransferStatus::kOk);
  send_chunks();
  EXPECT_EQ(rig.adapter.scanner().parameters().response_steps,
            scanner::factory_default().response_steps)
      << "the set is not applied before the commit";
  const auto commit = command(rig, request(protocol::DownloadCommitRequest{}));
  EXPECT_EQ(option1_state_bits(commit), 0b010) << "the commit answer: measuring again";
  EXPECT_EQ(state(), ScannerState::kMeasuring);
  EXPECT_EQ(rig.adapter.scanner().parameters().response_steps, 3);
  EXPECT_EQ(in() & (kInputOssd | kInputOperatingState), 0) << "bit 4 0, OSSD 0: start interlock";
  EXPECT_TRUE(rig.adapter.scanner().status().restart_interlock);
  rig.restart_pulse();
  EXPECT_TRUE(rig.ossd());
}

TEST_F(Configuring, RefusedCommitLeavesConfigurationWithTheSetUnchanged) {
  const auto before = rig.adapter.scanner().parameters();
  crc ^= 1U;  // the whole-set CRC the commit checks does not match
  ASSERT_EQ(transfer(rig, protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()),
                                                         crc})
                .status,
            protocol::TransferStatus::kOk);
  send_chunks();
  EXPECT_EQ(transfer(rig, protocol::DownloadCommitRequest{}).status,
            protocol::TransferStatus::kCrcMismatch);
  EXPECT_EQ(state(), ScannerState::kMeasuring);
  EXPECT_EQ(rig.adapter.scanner().parameters(), before);
  EXPECT_EQ(in() & kInputOperatingState, 0);
}

// A sync that ends while the download is open (PROFI_CMD_PROXY_END ok without a commit) leaves
// configuration with the set unchanged; nothing stays in configuration behind the proxy's back.
TEST_F(Configuring, SyncEndWithAnOpenDownloadLeavesConfiguration) {
  const auto before = rig.adapter.scanner().parameters();
  ASSERT_EQ(transfer(rig, protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()),
                                                         crc})
                .status,
            protocol::TransferStatus::kOk);
  ASSERT_EQ(state(), ScannerState::kConfiguration);
  const auto end = protocol::decode_proxy_end_answer(command(rig, {0x99, 0x00, 0x00, 0x00}));
  ASSERT_TRUE(end && end.value().accepted);
  EXPECT_EQ(state(), ScannerState::kMeasuring);
  EXPECT_FALSE(rig.adapter.proxy_session().download_open());
  EXPECT_EQ(rig.adapter.scanner().parameters(), before);
}

// A repeated DOWNLOAD_BEGIN restarts the download inside the configuration mode.
TEST_F(Configuring, RepeatedBeginStaysInConfiguration) {
  const protocol::DownloadBeginRequest begin{static_cast<std::uint16_t>(blob.size()), crc};
  ASSERT_EQ(transfer(rig, begin).status, protocol::TransferStatus::kOk);
  ASSERT_EQ(transfer(rig, begin).status, protocol::TransferStatus::kOk);
  EXPECT_EQ(state(), ScannerState::kConfiguration);
  send_chunks();
  EXPECT_EQ(transfer(rig, protocol::DownloadCommitRequest{}).status, protocol::TransferStatus::kOk);
  EXPECT_EQ(rig.adapter.scanner().parameters().response_steps, 3);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
