// The device side of a whole proxy sync ([docs/proxy-protocol.md], [RS4 manual §7.1, §7.2]) over
// the real stack: our class 1 master + F-host + Rs4Device on the memory bus, the block protocol
// ([RS4 manual §5.2.1]) with multi-block WRITEs, on the manual clock. The master side here is
// written out by hand (the proxy's ProxySync lives in proxy/).
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_segment.h"
#include "rs4/protocol/adapter_answer.h"
#include "rs4/protocol/parameter_transfer.h"
#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rs4sim::rs4::device {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using protocol::TransferStatus;

constexpr std::uint8_t kEnable = adapter::kOutputProxyEnable | 0x01;  // Proxy-Enable, pair 1

scanner::ParameterSet with_passwords() {
  auto s = scanner::factory_default();
  s.passwords[0] = {'L', 'E', 'U', 'Z', 'E', 0xFF, 0xFF, 0xFF};
  return s;
}

struct ProxySync : ::testing::Test {
  Rs4Segment seg{config()};

  static Rs4SegmentConfig config() {
    Rs4SegmentConfig c;
    c.device.switches = switches_for(4);
    c.master.address = 4;
    c.output_byte = kEnable;
    return c;
  }
  scanner::Scanner& rs4() { return seg.device().scanner(); }

  // Power on with `set` in the RS4, wait for data exchange and Proxy-Request.
  void boot(const scanner::ParameterSet& set = scanner::factory_default()) {
    ASSERT_TRUE(rs4().set_parameters(set, seg.now()));  // as parametrised before (RS4 off)
    seg.power_on();
    ASSERT_TRUE(seg.run_until([&] { return seg.in_data_exchange(); }, 5s));
    ASSERT_TRUE(
        seg.run_until([&] { return (seg.input_byte() & adapter::kInputProxyRequest) != 0; }, 31s));
  }
  // A command of any length: blocks 0..n-2 written here, the last (0xFFFF) by command().
  Bytes command(const Bytes& payload) {
    std::size_t offset = 0;
    std::uint16_t number = 0;
    while (payload.size() - offset > protocol::kMaxBlockPayload) {
      std::vector<std::uint8_t> record;
      const std::span<const std::uint8_t> part(payload.data() + offset, protocol::kMaxBlockPayload);
      EXPECT_FALSE(protocol::encode_block(0x00, number++, part, record));
      const auto w = seg.write_record(record);
      EXPECT_TRUE(w && !w->error);
      offset += protocol::kMaxBlockPayload;
    }
    const auto answer = seg.command(std::span<const std::uint8_t>(payload).subspan(offset));
    EXPECT_TRUE(answer) << answer.error().message();
    return answer ? answer.value() : Bytes{};
  }
  protocol::TransferAnswer transfer(const protocol::TransferRequest& r) {
    const auto bytes = protocol::encode_request(r);
    EXPECT_TRUE(bytes);
    const auto a = protocol::decode_answer(command(bytes ? bytes.value() : Bytes{}));
    EXPECT_TRUE(a) << a.error().message();
    return a ? a.value() : protocol::TransferAnswer{};
  }
  protocol::ProxyBeginAnswer begin() {
    const auto a = protocol::decode_proxy_begin_answer(command({0x98}));
    EXPECT_TRUE(a);
    return a ? a.value() : protocol::ProxyBeginAnswer{};
  }
  protocol::ProxyEndAnswer end(bool ok, std::uint16_t error = 0) {
    const auto a = protocol::decode_proxy_end_answer(
        command({0x99, static_cast<std::uint8_t>(ok ? 0 : 1), static_cast<std::uint8_t>(error >> 8),
                 static_cast<std::uint8_t>(error & 0xFF)}));
    EXPECT_TRUE(a);
    return a ? a.value() : protocol::ProxyEndAnswer{};
  }
  protocol::Identification identify() {
    const auto a = transfer(protocol::IdentifyRequest{});
    EXPECT_EQ(a.status, TransferStatus::kOk);
    const auto* id = a.body ? std::get_if<protocol::IdentifyAnswer>(&*a.body) : nullptr;
    return id ? id->identification : protocol::Identification{};
  }
  TransferStatus begin_download(const Bytes& blob, std::uint32_t crc) {
    return transfer(protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()), crc})
        .status;
  }
  protocol::TransferAnswer chunk(const Bytes& blob, std::uint8_t x) {
    const std::size_t off = std::size_t{x} * protocol::kMaxChunkSize;
    const auto n = std::min(protocol::kMaxChunkSize, blob.size() - off);
    return transfer(
        protocol::DownloadChunkRequest{x, std::span<const std::uint8_t>(blob).subspan(off, n)});
  }
  protocol::TransferAnswer download(const Bytes& blob, std::uint32_t crc) {
    EXPECT_EQ(begin_download(blob, crc), TransferStatus::kOk);
    for (std::uint8_t x = 0; std::size_t{x} * protocol::kMaxChunkSize < blob.size(); ++x) {
      const auto a = chunk(blob, x);
      EXPECT_EQ(a.status, TransferStatus::kOk);
      const auto* echo = a.body ? std::get_if<protocol::DownloadChunkAnswer>(&*a.body) : nullptr;
      const auto off = std::size_t{x} * protocol::kMaxChunkSize;
      const auto n = std::min(protocol::kMaxChunkSize, blob.size() - off);
      EXPECT_TRUE(echo &&
                  echo->echo_crc32 ==
                      scanner::crc32_iso_hdlc(std::span<const std::uint8_t>(blob).subspan(off, n)));
    }
    return transfer(protocol::DownloadCommitRequest{});
  }
  bool ossd_after_restart() {
    seg.set_output_byte(adapter::kOutputRestart | kEnable);
    seg.run_for(200ms);
    seg.set_output_byte(kEnable);
    return seg.run_until([&] { return (seg.input_byte() & adapter::kInputOssd) != 0; }, 500ms);
  }
  // Boot at factory settings, start the sync; the transfer form of the factory set after `edit`.
  template <class Edit>
  Bytes start_with_factory_and_stored(Edit edit) {
    boot();
    begin();
    auto stored = scanner::factory_default();
    edit(stored);
    return scanner::encode_for_transfer(stored);
  }
  std::uint16_t last_adapter_error() {
    const auto a = protocol::decode_last_error_answer(command({0x84}));
    return a ? a.value().uc2_error : 0;
  }
};

TEST_F(ProxySync, FullUploadReassemblesTheTransferForm) {
  auto set = with_passwords();
  set.response_steps = 6;
  set.pairs[2].protective_mm[100] = 1234;
  boot(set);
  EXPECT_EQ(begin(), (protocol::ProxyBeginAnswer{protocol::SyncReason::kPowerUp,
                                                 protocol::SyncDirection::kVerify, false}));
  const auto id = identify();
  EXPECT_EQ(identify(), id);  // every read twice
  Bytes blob;
  for (std::uint8_t x = 0; x < id.chunk_count(); ++x) {
    const auto a = transfer(protocol::UploadChunkRequest{x});
    ASSERT_EQ(a, transfer(protocol::UploadChunkRequest{x}));
    const auto* up = a.body ? std::get_if<protocol::UploadChunkAnswer>(&*a.body) : nullptr;
    ASSERT_NE(up, nullptr);
    ASSERT_EQ(up->crc32, scanner::crc32_iso_hdlc(up->data));
    blob.insert(blob.end(), up->data.begin(), up->data.end());
  }
  EXPECT_EQ(blob, scanner::encode_for_transfer(rs4().parameters()));
  EXPECT_EQ(scanner::crc32_iso_hdlc(blob), id.set_crc32);
  EXPECT_FALSE(ossd_after_restart());  // Proxy-Enable 1: not before END ok
  EXPECT_EQ(end(true), (protocol::ProxyEndAnswer{true, false}));
  EXPECT_TRUE(ossd_after_restart());
}

TEST_F(ProxySync, FullDownloadChangesTheSetAndKeepsThePasswords) {
  boot(with_passwords());  // factory apart from the passwords
  EXPECT_EQ(begin().direction, protocol::SyncDirection::kDownload);
  auto stored = scanner::factory_default();
  stored.response_steps = 4;
  stored.pairs[0].warning_mm.fill(3000);
  const auto blob = scanner::encode_for_transfer(stored);
  const auto crc = scanner::crc32_iso_hdlc(blob);
  const auto before = identify().change_counter;
  const auto commit = download(blob, crc);
  ASSERT_EQ(commit.status, TransferStatus::kOk);
  EXPECT_EQ(std::get<protocol::DownloadCommitAnswer>(*commit.body).active_crc32, crc);
  const auto id = identify();  // checksum re-read
  EXPECT_EQ(id.set_crc32, crc);
  EXPECT_FALSE(id.factory_default());
  EXPECT_EQ(id.change_counter, before + 1);
  EXPECT_EQ(rs4().parameters().response_steps, 4);
  EXPECT_EQ(rs4().parameters().passwords, with_passwords().passwords);
  EXPECT_EQ(rs4().parameters().identity.serial_number, 0x00012345U);
  EXPECT_EQ(end(true).accepted, true);
  EXPECT_TRUE(ossd_after_restart());
}

TEST_F(ProxySync, CrcMismatchAtCommitLeavesTheSetUnchanged) {
  const auto blob = start_with_factory_and_stored([](auto& s) { s.response_steps = 2; });
  EXPECT_EQ(download(blob, scanner::crc32_iso_hdlc(blob) ^ 1U).status,
            TransferStatus::kCrcMismatch);
  EXPECT_TRUE(rs4().factory_settings());
  EXPECT_EQ(rs4().change_counter(), 1);  // only boot()'s write
}

TEST_F(ProxySync, InvalidSetAtCommitLeavesTheSetUnchanged) {
  const auto blob = start_with_factory_and_stored([](auto& s) { s.start_pair = 7; });
  EXPECT_EQ(download(blob, scanner::crc32_iso_hdlc(blob)).status, TransferStatus::kInvalidSet);
  EXPECT_TRUE(rs4().factory_settings());
}

TEST_F(ProxySync, OutOfOrderChunkAndDownloadOutsideASync) {
  boot();
  const auto blob = scanner::encode_for_transfer(scanner::factory_default());
  // Outside a sync, without the password: the RS4 refuses it with 0x53 0503 (the one password
  // rule of both paths, [docs/decisions.md#rs4-one-command-set]), nothing opens.
  const auto request = protocol::encode_request(protocol::DownloadBeginRequest{
      static_cast<std::uint16_t>(blob.size()), 0});
  ASSERT_TRUE(request);
  const auto refused = command(request.value());
  ASSERT_GE(refused.size(), 6U);
  EXPECT_EQ(refused[0], 0x53);
  EXPECT_EQ(Bytes(refused.end() - 6, refused.end()), (Bytes{0x05, 0x03, 0x00, 0x62, 0x00, 0x05}));
  EXPECT_FALSE(seg.device().adapter().proxy_session().download_open());
  begin();
  ASSERT_EQ(begin_download(blob, 0), TransferStatus::kOk);
  EXPECT_EQ(chunk(blob, 1).status, TransferStatus::kBadChunk);
  EXPECT_EQ(chunk(blob, 0).status, TransferStatus::kOk);
  EXPECT_EQ(chunk(blob, 0).status, TransferStatus::kBadChunk);
}

TEST_F(ProxySync, FlowStateIsProxyBusyDuringTheSync) {
  boot();
  const auto flow = [&] {
    const auto r = seg.read_record();
    return r && !r->error && !r->data.empty() ? r->data[0] : 0;
  };
  EXPECT_EQ(flow() & 0x70, 0x40);  // 100 normal
  begin();
  EXPECT_EQ(flow() & 0x70, 0x30);  // 011 proxy busy ([RS4 manual §5.2.1] table 5.2-2)
  end(true);
  EXPECT_EQ(flow() & 0x70, 0x40);
}

TEST_F(ProxySync, FailedEndResetsToFactoryLogsTheErrorAndRequestsAgain) {
  auto set = with_passwords();
  set.response_steps = 3;
  boot(set);
  begin();
  EXPECT_EQ(end(false, 0x2B23), (protocol::ProxyEndAnswer{true, true}));
  EXPECT_TRUE(rs4().factory_settings());
  EXPECT_EQ(rs4().parameters().passwords, with_passwords().passwords);
  EXPECT_EQ(last_adapter_error(), 0x2B23);
  ASSERT_TRUE(
      seg.run_until([&] { return (seg.input_byte() & adapter::kInputProxyRequest) != 0; }, 100ms));
  EXPECT_FALSE(ossd_after_restart());
  EXPECT_EQ(begin(), (protocol::ProxyBeginAnswer{protocol::SyncReason::kRetry,
                                                 protocol::SyncDirection::kDownload, true}));
}

// [RS4 manual §5.1.1] bit 2 "Tritt während der Parameterkontrolle ein Fehler auf, wird es wieder
// auf 1 gesetzt": after 99 success the adapter still takes a failure report (the proxy's
// background verify failed) — accepted, factory settings, Proxy-Request, OSSD bit 0 — but only
// one, and only until the next sync starts; a second success is not accepted.
TEST_F(ProxySync, FailureReportAfterTheReleaseWithdrawsItUntilTheNextSync) {
  auto set = scanner::factory_default();
  set.response_steps = 3;
  boot(set);
  begin();
  EXPECT_EQ(end(true, 0), (protocol::ProxyEndAnswer{true, false}));
  EXPECT_TRUE(ossd_after_restart());
  EXPECT_EQ(end(true, 0), (protocol::ProxyEndAnswer{false, false})) << "no second success";
  EXPECT_EQ(end(false, 0x2B09), (protocol::ProxyEndAnswer{true, true})) << "verify failed";
  EXPECT_TRUE(rs4().factory_settings());
  EXPECT_EQ(last_adapter_error(), 0x2B09);
  ASSERT_TRUE(
      seg.run_until([&] { return (seg.input_byte() & adapter::kInputProxyRequest) != 0; }, 100ms));
  EXPECT_FALSE(ossd_after_restart());
  EXPECT_EQ(end(false, 0), (protocol::ProxyEndAnswer{false, true})) << "taken once";
  // A new sync closes the window: after its success one report is taken again, not before.
  EXPECT_EQ(begin(), (protocol::ProxyBeginAnswer{protocol::SyncReason::kRetry,
                                                 protocol::SyncDirection::kDownload, true}));
  EXPECT_EQ(end(true, 0), (protocol::ProxyEndAnswer{true, true}));
  EXPECT_TRUE(ossd_after_restart());
}

TEST_F(ProxySync, UserCommandDuringTheSyncAbortsItWith0x2B01) {
  boot();
  begin();
  EXPECT_EQ(last_adapter_error(), 0x2B01);  // 0x84 is itself a user command
  EXPECT_EQ(end(true).accepted, false);     // the sync is over
  ASSERT_TRUE(
      seg.run_until([&] { return (seg.input_byte() & adapter::kInputProxyRequest) != 0; }, 100ms));
  EXPECT_EQ(begin().reason, protocol::SyncReason::kRetry);
}

TEST_F(ProxySync, LinkLossMidDownloadFallsBackToFactorySettings) {
  auto set = with_passwords();
  set.response_steps = 5;
  boot(set);
  begin();
  const auto blob = scanner::encode_for_transfer(scanner::factory_default());
  ASSERT_EQ(begin_download(blob, scanner::crc32_iso_hdlc(blob)), TransferStatus::kOk);
  ASSERT_EQ(chunk(blob, 0).status, TransferStatus::kOk);
  seg.bus().set_silenced(seg.master().config().address, true);  // the master falls silent
  ASSERT_TRUE(seg.run_until([&] { return !seg.device().adapter().view().connected; }, 2s));
  EXPECT_TRUE(rs4().factory_settings());
  EXPECT_EQ(rs4().parameters().passwords, with_passwords().passwords);
  EXPECT_FALSE(seg.device().adapter().proxy_session().download_open());
  seg.bus().set_silenced(seg.master().config().address, false);
  ASSERT_TRUE(seg.run_until(
      [&] {
        seg.ack_rei();  // the F-host acknowledges the communication error it saw
        return (seg.input_byte() & adapter::kInputProxyRequest) != 0;
      },
      5s));
  EXPECT_EQ(begin(), (protocol::ProxyBeginAnswer{protocol::SyncReason::kRetry,
                                                 protocol::SyncDirection::kDownload, true}));
}

}  // namespace
}  // namespace rs4sim::rs4::device
