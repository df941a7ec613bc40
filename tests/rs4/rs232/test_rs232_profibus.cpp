// The RS232 port beside the PROFIBUS station of the same RS4 ([RS4 manual §7.1, §7.2],
// [RS4 manual §5.1.1] bits 2 and 3): attach/detach seen in the cyclic input byte through the
// F-host, and the manual's scenario 2 over the live RS232 path: parametrise with the
// password (the proxy payloads, docs/proxy-protocol.md, RS232-framed), remove the adapter,
// Proxy-Request asks for an upload.
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_segment.h"
#include "rs4/rs232/rs232_client.h"
#include "rs4/rs232/rs232_port.h"
#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::rs232 {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

const CommandOptions kPassword{.acknowledge = false, .password = make_password("ROD4LE")};

struct Profibus {
  Profibus() : segment(config()), port(segment.device().adapter()) {}
  static device::Rs4SegmentConfig config() {
    device::Rs4SegmentConfig c;
    c.device.boot_time = 100ms;
    c.auto_ack_rei = true;
    return c;
  }
  // The first non-0x23 answer to one framed command (the port may be streaming).
  protocol::TransferAnswer transfer(const protocol::TransferRequest& request,
                                    const CommandOptions& options = {}) {
    port.on_bytes(encode_transfer(request, options).value(), segment.now());
    AnswerReader reader;
    while (auto f = port.take_transmit()) {
      for (auto& a : reader.feed(*f)) {
        if (!a) continue;
        if (const auto* t = std::get_if<protocol::TransferAnswer>(&a.value())) return *t;
        if (const auto* e = std::get_if<protocol::ErrorTelegram>(&a.value())) {
          last_error = e->report;
        }
      }
    }
    return {};
  }
  // Reads the set over RS232 (IDENTIFY, UPLOAD_CHUNK 0..n-1).
  Bytes upload() {
    const auto id = transfer(protocol::IdentifyRequest{});
    const auto& i = std::get<protocol::IdentifyAnswer>(*id.body).identification;
    Bytes blob;
    for (std::size_t c = 0; c < i.chunk_count(); ++c) {
      const auto a = transfer(protocol::UploadChunkRequest{static_cast<std::uint8_t>(c)});
      const auto& d = std::get<protocol::UploadChunkAnswer>(*a.body).data;
      blob.insert(blob.end(), d.begin(), d.end());
    }
    return blob;
  }
  // Sends the chunks of a begun download (DOWNLOAD_CHUNK 0..n-1, with the password) and
  // returns their answers in order; stops after the first answer that is not OK.
  std::vector<protocol::TransferAnswer> download_chunks(const protocol::DownloadBeginAnswer& b,
                                                        const Bytes& blob) {
    std::vector<protocol::TransferAnswer> answers;
    for (std::size_t c = 0; c < b.chunk_count; ++c) {
      const std::size_t off = c * b.chunk_size;
      const std::size_t len = std::min<std::size_t>(b.chunk_size, blob.size() - off);
      answers.push_back(transfer(protocol::DownloadChunkRequest{static_cast<std::uint8_t>(c),
                                                                std::span(blob).subspan(off, len)},
                                 kPassword));
      if (answers.back().status != protocol::TransferStatus::kOk) break;
    }
    return answers;
  }
  // Powers the RS4 on and runs until data exchange; false if it is not there within 5 s.
  bool reach_data_exchange() {
    segment.power_on();
    return segment.run_until([&] { return segment.in_data_exchange(); }, 5s);
  }
  // Plugs the PC adapter in and lets 50 ms pass.
  void attach_adapter() {
    port.attach(segment.now());
    segment.run_for(50ms);
  }
  std::uint8_t input() const { return segment.input_byte(); }

  device::Rs4Segment segment;
  Rs232Port port;
  protocol::ErrorReport last_error;
};

TEST(Rs232Profibus, AttachedAtStartUpThenRemovedSetsProxyRequest) {
  Profibus p;
  p.port.attach(p.segment.now());  // `--pc-adapter attached`
  p.segment.power_on();
  ASSERT_TRUE(p.segment.run_until(
      [&] { return p.segment.in_data_exchange() && (p.input() & adapter::kInputRs232Active); },
      5s));
  p.segment.run_for(500ms);
  EXPECT_EQ(p.input() & adapter::kInputProxyRequest, 0);  // not while attached
  EXPECT_TRUE(p.port.reachable());
  p.port.detach(p.segment.now());
  p.segment.run_for(100ms);
  EXPECT_EQ(p.input() & adapter::kInputRs232Active, 0);
  EXPECT_NE(p.input() & adapter::kInputProxyRequest, 0);  // removal always requests a sync
  EXPECT_EQ(p.segment.device().adapter().proxy_session().reason(),
            protocol::SyncReason::kPcAdapterRemoved);
}

TEST(Rs232Profibus, ScenarioTwoParametriseOverRs232ThenDetach) {
  Profibus p;
  ASSERT_TRUE(p.reach_data_exchange());
  p.segment.run_for(500ms);
  p.attach_adapter();
  ASSERT_NE(p.input() & adapter::kInputRs232Active, 0);
  ASSERT_TRUE(p.port.reachable());

  auto set = scanner::decode_transfer_form(p.upload());
  ASSERT_TRUE(set) << set.error().message();
  auto changed = set.value();
  changed.response_steps = 3;
  const auto blob = scanner::encode_for_transfer(changed);
  const auto crc = scanner::crc32_iso_hdlc(blob);

  // Without the password the download is refused (0x53 0503) and nothing opens.
  (void)p.transfer(protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()), crc});
  EXPECT_EQ(p.last_error.number, 0x0503);

  auto begin = p.transfer(
      protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()), crc}, kPassword);
  ASSERT_EQ(begin.status, protocol::TransferStatus::kOk);
  const auto& b = std::get<protocol::DownloadBeginAnswer>(*begin.body);
  for (const auto& a : p.download_chunks(b, blob)) {
    ASSERT_EQ(a.status, protocol::TransferStatus::kOk);
  }
  const auto commit = p.transfer(protocol::DownloadCommitRequest{}, kPassword);
  ASSERT_EQ(commit.status, protocol::TransferStatus::kOk);
  EXPECT_EQ(std::get<protocol::DownloadCommitAnswer>(*commit.body).active_crc32, crc);
  EXPECT_EQ(p.segment.device().scanner().parameters().response_steps, 3);

  p.port.detach(p.segment.now());
  p.segment.run_for(100ms);
  EXPECT_NE(p.input() & adapter::kInputProxyRequest, 0);
  EXPECT_EQ(adapter::sync_direction(p.segment.device().adapter().proxy_session().reason(),
                                    p.segment.device().scanner().factory_settings()),
            protocol::SyncDirection::kUpload);
}

TEST(Rs232Profibus, AnInvalidSetIsRefusedAndChangesNothing) {
  Profibus p;
  ASSERT_TRUE(p.reach_data_exchange());
  p.attach_adapter();
  const auto before = p.segment.device().scanner().parameters();
  auto blob = p.upload();
  blob[1] ^= 0x55;  // header damaged: does not decode
  const auto crc = scanner::crc32_iso_hdlc(blob);
  (void)p.transfer(protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()), crc},
                   kPassword);
  for (std::uint8_t c = 0; c * std::size_t{1024} < blob.size(); ++c) {
    const std::size_t off = c * std::size_t{1024};
    (void)p.transfer(
        protocol::DownloadChunkRequest{
            c, std::span(blob).subspan(off, std::min<std::size_t>(1024, blob.size() - off))},
        kPassword);
  }
  EXPECT_EQ(p.transfer(protocol::DownloadCommitRequest{}, kPassword).status,
            protocol::TransferStatus::kInvalidSet);
  EXPECT_EQ(p.segment.device().scanner().parameters(), before);
  EXPECT_TRUE(p.segment.in_data_exchange());  // the PROFIBUS side is undisturbed
}

// [RS4 manual §7.1.2] "Natürlich schaltet das OSSD-Signal während eines Downloads über diese
// Schnittstelle aus, wenn der Datensatz im RS4 verändert wird": a download over the PC adapter
// puts the RS4 into configuration from its DOWNLOAD_BEGIN (the RS232 answers at once): option 1
// 011, input bit 4 at once, the OSSD bit 10 ms later ([RS4 manual §6.6]), both sides of the
// bound; the commit leaves it with the start interlock.
TEST(Rs232Profibus, DownloadOverRs232SwitchesTheOssdOffFromItsStart) {
  Profibus p;
  ASSERT_TRUE(p.reach_data_exchange());
  p.segment.run_for(300ms);
  p.segment.set_output_byte(adapter::kOutputRestart | 0x01);
  p.segment.run_for(200ms);
  p.segment.set_output_byte(0x01);
  ASSERT_TRUE(p.segment.run_until([&] { return (p.input() & adapter::kInputOssd) != 0; }, 500ms));
  p.attach_adapter();
  ASSERT_TRUE(p.port.reachable());
  const auto& a = p.segment.device().adapter();
  ASSERT_EQ(a.input_byte() & (adapter::kInputOssd | adapter::kInputOperatingState),
            adapter::kInputOssd);

  auto changed = scanner::factory_default();
  changed.response_steps = 3;
  const auto blob = scanner::encode_for_transfer(changed);
  const auto crc = scanner::crc32_iso_hdlc(blob);
  const auto begin = p.transfer(
      protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()), crc}, kPassword);
  const auto at = p.segment.now();
  ASSERT_EQ(begin.status, protocol::TransferStatus::kOk);
  EXPECT_EQ(begin.options.state, protocol::Option1State::kConfiguration);
  EXPECT_EQ(p.segment.device().scanner().status().state, scanner::ScannerState::kConfiguration);
  EXPECT_FALSE(p.segment.device().scanner().ossd());
  EXPECT_NE(a.input_byte() & adapter::kInputOperatingState, 0) << "bit 4 at once";
  EXPECT_NE(a.input_byte() & adapter::kInputOssd, 0) << "the OSSD bit 10 ms later";
  p.segment.run_for(9ms);
  EXPECT_NE(a.input_byte() & adapter::kInputOssd, 0) << "9 ms";
  p.segment.run_for(1ms);
  EXPECT_EQ(p.segment.now() - at, 10ms);
  EXPECT_EQ(a.input_byte() & adapter::kInputOssd, 0) << "10 ms";

  const auto& b = std::get<protocol::DownloadBeginAnswer>(*begin.body);
  for (const auto& ch : p.download_chunks(b, blob)) {
    ASSERT_EQ(ch.status, protocol::TransferStatus::kOk);
    EXPECT_EQ(ch.options.state, protocol::Option1State::kConfiguration);
  }
  const auto commit = p.transfer(protocol::DownloadCommitRequest{}, kPassword);
  ASSERT_EQ(commit.status, protocol::TransferStatus::kOk);
  EXPECT_EQ(commit.options.state, protocol::Option1State::kMeasuring);
  EXPECT_EQ(p.segment.device().scanner().parameters().response_steps, 3);
  p.segment.run_for(20ms);
  EXPECT_EQ(a.input_byte() & (adapter::kInputOssd | adapter::kInputOperatingState), 0)
      << "protecting again, OSSD 0 until the restart (start interlock)";
  EXPECT_TRUE(p.segment.device().scanner().status().restart_interlock);
}

// Removing the PC adapter in the middle of an RS232 download discards it: the RS4 leaves its
// configuration mode with its set unchanged.
TEST(Rs232Profibus, RemovalDuringAnRs232DownloadLeavesConfiguration) {
  Profibus p;
  ASSERT_TRUE(p.reach_data_exchange());
  p.attach_adapter();
  const auto before = p.segment.device().scanner().parameters();
  const auto blob = scanner::encode_for_transfer(before);
  ASSERT_EQ(p.transfer(protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()),
                                                      scanner::crc32_iso_hdlc(blob)},
                       kPassword)
                .status,
            protocol::TransferStatus::kOk);
  ASSERT_EQ(p.segment.device().scanner().status().state, scanner::ScannerState::kConfiguration);
  p.port.detach(p.segment.now());
  EXPECT_EQ(p.segment.device().scanner().status().state, scanner::ScannerState::kMeasuring);
  EXPECT_EQ(p.segment.device().scanner().parameters(), before);
  EXPECT_EQ(p.segment.device().scanner().change_counter(), 0);
}

}  // namespace
}  // namespace rs4sim::rs4::rs232
