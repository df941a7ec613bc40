// One RS4 command set behind both paths ([RS4 manual §5.2.1] "Alle Kommandos werden transparent
// von und zur RS232 des RS4 übertragen"; [RS4 manual §5.1.1] bit 4 "Der RS4 kann sowohl über
// den PROFIBUS (C1- oder C2-Dienst) als auch über die PC-Schnittstelle und den PC-Adapter
// parametriert werden"): over PROFIBUS the RS4 answers the commands of its RS232 (docs/rs232.md)
// with the same password rule; each remaining difference of the paths is pinned here
// [docs/decisions.md#rs4-one-command-set]. Expected bytes are written from docs/rs232.md.
#include "proxy_rig.h"
#include "rs4/adapter/rs4_commands.h"
#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

using protocol::TransferStatus;

// OPT1 0x21 (bit 5: password follows) + "ROD4LE" FF FF, the drivers' factory password.
const Bytes kWithPassword{0x21, 0x52, 0x4F, 0x44, 0x34, 0x4C, 0x45, 0xFF, 0xFF};

Bytes with(std::uint8_t code, const Bytes& options, const Bytes& data) {
  Bytes b{code};
  b.insert(b.end(), options.begin(), options.end());
  b.insert(b.end(), data.begin(), data.end());
  return b;
}

struct CommandSet : ::testing::Test {
  Rig rig;
  void SetUp() override { ASSERT_TRUE(rig.boot_and_release()); }
  [[nodiscard]] const scanner::Scanner& rs4() const { return rig.adapter.scanner(); }
};

// 0x20 over PROFIBUS, as over RS232: with the password acknowledged (0x16 20) and applied
// through the configuration mode (start interlock afterwards: OSSD 0 until the restart); the
// changed set is offered to the proxy (Proxy-Request, reason 4: an upload).
TEST_F(CommandSet, MeasurementWindowOverProfibusWithThePassword) {
  // The power-up's Proxy-Request first ends with a sync, so that the one below is the window's.
  ASSERT_TRUE(protocol::decode_proxy_begin_answer(command(rig, {0x98})));
  ASSERT_TRUE(protocol::decode_proxy_end_answer(command(rig, {0x99, 0x00, 0x00, 0x00})));
  ASSERT_EQ(rig.adapter.input_byte() & kInputProxyRequest, 0);
  const auto a = command(rig, with(0x20, kWithPassword, {0x04, 0x00, 0x00, 0x02, 0x10}));
  ASSERT_GE(a.size(), 2U);
  EXPECT_EQ(a.front(), 0x16) << "acknowledged: the READ finds an answer";
  EXPECT_EQ(a.back(), 0x20);
  EXPECT_EQ(rs4().parameters().measurement.resolution, 4);
  EXPECT_EQ(rs4().parameters().measurement.stop, 528);
  EXPECT_EQ(rs4().change_counter(), 1);
  EXPECT_TRUE(rs4().status().restart_interlock) << "the window went through configuration";
  EXPECT_NE(rig.adapter.input_byte() & kInputProxyRequest, 0);
  EXPECT_EQ(rig.adapter.proxy_session().reason(), protocol::SyncReason::kUserParametrisation);
  rig.run(40ms);
  EXPECT_FALSE(rig.ossd());
  rig.restart_pulse();
  EXPECT_TRUE(rig.ossd());
}

// Without the password: 53 | options | 05 03 | 00 20 | 00 05 (docs/rs232.md "Reactions"),
// nothing changes and the RS4 keeps protecting (a command it knows, [RS4 manual §5.2.2]).
TEST_F(CommandSet, MeasurementWindowWithoutThePasswordIsRefusedAsOnRs232) {
  const auto before = rs4().parameters();
  const auto a = command(rig, with(0x20, {0x01}, {0x04, 0x00, 0x00, 0x02, 0x10}));
  ASSERT_GE(a.size(), 6U);
  EXPECT_EQ(a[0], 0x53);
  EXPECT_EQ(Bytes(a.end() - 6, a.end()), (Bytes{0x05, 0x03, 0x00, 0x20, 0x00, 0x05}));
  EXPECT_EQ(rs4().parameters(), before);
  EXPECT_EQ(rs4().status().state, scanner::ScannerState::kMeasuring);
  // With OPT1 bit 6 the refusal is 17 | options | 20 | 05 03 instead.
  const auto nak = command(rig, with(0x20, {0x41}, {0x04, 0x00, 0x00, 0x02, 0x10}));
  ASSERT_GE(nak.size(), 4U);
  EXPECT_EQ(nak[0], 0x17);
  EXPECT_EQ(Bytes(nak.end() - 3, nak.end()), (Bytes{0x20, 0x05, 0x03}));
}

// 0x10 (password check), 0x22 (stream switch) and 0x19 (baud) are known over PROFIBUS: no 0x53
// "unknown command", no error state. 0x19/0x22 act on the PC-adapter line only: over PROFIBUS
// they are checked and acknowledged (DECISION; the tunnel has no line rate and forwards scans
// through PROFI_CMD_GET_RS4_DATA, [RS4 manual §5.2.2]).
TEST_F(CommandSet, PasswordCheckStreamSwitchAndBaudAreKnownOverProfibus) {
  EXPECT_EQ(command(rig, with(0x10, kWithPassword, {})).front(), 0x16);
  EXPECT_EQ(command(rig, with(0x22, {0x01}, {0x01})).front(), 0x16);
  EXPECT_EQ(command(rig, with(0x19, {0x01}, {0x00, 0x05})).front(), 0x16);
  const auto bad = command(rig, with(0x19, {0x01}, {0x00, 0x09}));  // no rate code 9
  ASSERT_GE(bad.size(), 6U);
  EXPECT_EQ(Bytes(bad.end() - 6, bad.end()), (Bytes{0x05, 0x04, 0x00, 0x19, 0x00, 0x05}));
  EXPECT_EQ(rs4().status().state, scanner::ScannerState::kMeasuring);
  EXPECT_TRUE(rs4().ossd());
  // 0x10 without the password: 05 03 as on RS232.
  const auto refused = command(rig, with(0x10, {0x01}, {}));
  ASSERT_GE(refused.size(), 6U);
  EXPECT_EQ(Bytes(refused.end() - 6, refused.end()), (Bytes{0x05, 0x03, 0x00, 0x10, 0x00, 0x05}));
}

// A download outside a proxy sync: refused without the password (05 03, as on RS232), done with
// it (a user's parametrisation over PROFIBUS), and the adapter asks the proxy to take the new set
// (Proxy-Request, reason 2: the direction is an upload) without withdrawing the OSSD bit's
// release.
TEST_F(CommandSet, DownloadOutsideASyncNeedsThePasswordAndAsksForAnUpload) {
  auto set = scanner::factory_default();
  set.response_steps = 3;
  const auto blob = scanner::encode_for_transfer(set);
  const auto crc = scanner::crc32_iso_hdlc(blob);
  const Bytes begin{0x21,
                    0x3B,
                    static_cast<std::uint8_t>(crc >> 24),
                    static_cast<std::uint8_t>(crc >> 16),
                    static_cast<std::uint8_t>(crc >> 8),
                    static_cast<std::uint8_t>(crc)};
  const auto refused = command(rig, with(0x62, {0x01}, begin));
  ASSERT_GE(refused.size(), 6U);
  EXPECT_EQ(refused[0], 0x53);
  EXPECT_EQ(Bytes(refused.end() - 6, refused.end()), (Bytes{0x05, 0x03, 0x00, 0x62, 0x00, 0x05}));
  EXPECT_FALSE(rig.adapter.proxy_session().download_open());

  // Proxy-Request from power-up still pending here: a sync end first clears it, so that the
  // request below is the download's.
  ASSERT_TRUE(protocol::decode_proxy_begin_answer(command(rig, {0x98})));
  ASSERT_TRUE(protocol::decode_proxy_end_answer(command(rig, {0x99, 0x00, 0x00, 0x00})));
  ASSERT_EQ(rig.adapter.input_byte() & kInputProxyRequest, 0);

  const auto ok = protocol::decode_answer(command(rig, with(0x62, kWithPassword, begin)));
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok.value().status, TransferStatus::kOk);
  for (std::size_t x = 0; x * protocol::kMaxChunkSize < blob.size(); ++x) {
    const std::size_t off = x * protocol::kMaxChunkSize;
    const std::size_t n = std::min(protocol::kMaxChunkSize, blob.size() - off);
    Bytes data{static_cast<std::uint8_t>(x)};
    data.insert(data.end(), blob.begin() + static_cast<std::ptrdiff_t>(off),
                blob.begin() + static_cast<std::ptrdiff_t>(off + n));
    const auto a = protocol::decode_answer(command(rig, with(0x63, kWithPassword, data)));
    ASSERT_TRUE(a && a.value().status == TransferStatus::kOk) << "chunk " << x;
  }
  const auto commit = protocol::decode_answer(command(rig, with(0x64, kWithPassword, {})));
  ASSERT_TRUE(commit);
  EXPECT_EQ(commit.value().status, TransferStatus::kOk);
  EXPECT_EQ(rs4().parameters().response_steps, 3);
  EXPECT_NE(rig.adapter.input_byte() & kInputProxyRequest, 0);
  EXPECT_EQ(rig.adapter.proxy_session().reason(), protocol::SyncReason::kUserParametrisation);
  EXPECT_EQ(sync_direction(rig.adapter.proxy_session().reason(), rs4().factory_settings()),
            protocol::SyncDirection::kUpload);
  EXPECT_TRUE(rig.adapter.released()) << "the OSSD bit's release is kept";
}

// Inside the proxy's sync the transfer needs no password (DECISION: the Proxy-FB holds none,
// [RS4 manual §7.2.4]); the same DOWNLOAD_BEGIN bytes without a password are accepted.
TEST_F(CommandSet, TheProxysOwnDownloadNeedsNoPassword) {
  ASSERT_TRUE(protocol::decode_proxy_begin_answer(command(rig, {0x98})));
  const auto a = protocol::decode_answer(
      command(rig, with(0x62, {0x01}, {0x21, 0x3B, 0x9C, 0xC1, 0x9E, 0x11})));
  ASSERT_TRUE(a);
  EXPECT_EQ(a.value().status, TransferStatus::kOk);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
