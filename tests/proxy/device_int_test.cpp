// ProxySync against the real device: our class 1 master + F-host + Rs4Device on the memory bus
// (Rs4Segment), the archive on a real SQLite file, on the manual clock ([RS4 manual §7.1, §7.2]).
#include "proxy/proxy_sync.h"
#include "proxy/retentive.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_segment.h"
#include "rs4/scanner/parameter_codec.h"
#include "storage/sqlite_archive.h"
#include "tests/storage/archive_test_support.h"

#include <gtest/gtest.h>

namespace rs4sim::proxy {
namespace {

using namespace std::chrono_literals;
constexpr std::uint8_t kEnable = rs4::adapter::kOutputProxyEnable | 0x01;

struct DeviceSync : ::testing::Test {
  static rs4::device::Rs4SegmentConfig config() {
    rs4::device::Rs4SegmentConfig c;
    c.device.switches = rs4::device::switches_for(4);
    c.master.address = 4;
    c.output_byte = kEnable;
    return c;
  }
  void boot(const rs4::scanner::ParameterSet& set) {
    ASSERT_TRUE(seg.device().scanner().set_parameters(set, seg.now()));
    seg.power_on();
    ASSERT_TRUE(seg.run_until([&] { return seg.in_data_exchange(); }, 5s));
    ASSERT_TRUE(seg.run_until(
        [&] { return (seg.input_byte() & rs4::adapter::kInputProxyRequest) != 0; }, 31s));
  }
  RecordResult exchange(const RecordRequest& request) {
    const auto* w = std::get_if<RecordWrite>(&request);
    const auto r = w != nullptr ? seg.write_record(w->data)
                                : seg.read_record(std::get<RecordRead>(request).length);
    if (!r) return RecordResult::no_response();
    if (r->error) {
      if (!r->negative) return RecordResult::no_response();
      return RecordResult::negative(static_cast<std::uint8_t>(r->negative->error_code_1),
                                    r->negative->error_code_2);
    }
    return RecordResult::success({r->data.begin(), r->data.end()});
  }
  // One sync to its end (failure report and background verify included).
  bool run_sync(dp::Duration timeout = 200s, std::optional<Step> stop_at = std::nullopt) {
    sync.set_proxy_enable(true);
    sync.set_input_byte(seg.input_byte());
    if (!sync.ready(seg.now())) return false;
    sync.start(seg.now());
    const auto end = seg.now() + timeout;
    while (seg.now() < end) {
      sync.set_input_byte(seg.input_byte());
      if (!sync.active()) return true;
      if (stop_at && sync.progress().step == *stop_at) return true;
      if (auto req = sync.take_request(seg.now())) {
        ++records;
        sync.on_record_result(exchange(*req), seg.now());
      } else {
        seg.run_for(10ms);
        sync.tick(seg.now());
      }
    }
    return false;
  }
  storage::Result<storage::VersionInfo> store(const rs4::scanner::ParameterSet& set,
                                              const std::string& serial) {
    const auto blob = rs4::scanner::encode_for_transfer(set);
    storage::StoreRequest r;
    r.station = {"bus", 4};
    r.serial_number = serial;
    r.blob = blob;
    r.crc32 = rs4::scanner::transfer_checksum(set);
    return archive->store(r);
  }
  bool ossd_after_restart() {
    seg.set_output_byte(rs4::adapter::kOutputRestart | kEnable);
    seg.run_for(200ms);
    seg.set_output_byte(kEnable);
    return seg.run_until([&] { return (seg.input_byte() & rs4::adapter::kInputOssd) != 0; }, 500ms);
  }

  rs4::device::Rs4Segment seg{config()};
  storage::testing::TempDir dir;
  std::unique_ptr<storage::SqliteArchive> archive =
      storage::SqliteArchive::open(dir.file("a.sqlite3")).value();
  static ProxySyncConfig sync_config() {
    ProxySyncConfig c;
    c.station = {"bus", 4};
    return c;
  }
  ProxySync sync{sync_config(), *archive};
  int records = 0;
};

TEST_F(DeviceSync, FirstCommissioning) {
  boot(rs4::scanner::factory_default());
  ASSERT_TRUE(run_sync());
  EXPECT_EQ(sync.outputs().error_number_fb, 0) << std::hex << sync.outputs().error_number_fb;
  EXPECT_TRUE(sync.outputs().config_set_to_default);
  EXPECT_TRUE(ossd_after_restart());
}

TEST_F(DeviceSync, LearnThenNormalStart) {
  auto set = rs4::scanner::factory_default();
  set.response_steps = 6;
  boot(set);
  ASSERT_TRUE(run_sync());
  EXPECT_EQ(sync.outputs(), FbOutputs{})
      << std::hex << sync.outputs().error_number_fb << " rs4 " << sync.outputs().error_number_rs4;
  const auto current = archive->current({"bus", 4});
  ASSERT_TRUE(current);
  EXPECT_EQ(current.value().set.blob, rs4::scanner::encode_for_transfer(set));
  EXPECT_TRUE(ossd_after_restart());
  // Power cycle: normal start, consistent → released at once, verified in the background.
  seg.power_off();
  seg.run_for(1s);
  seg.power_on();
  ASSERT_TRUE(seg.run_until([&] { return seg.in_data_exchange(); }, 5s));
  ASSERT_TRUE(seg.run_until(
      [&] {
        seg.ack_rei();  // the F-host passivated on the communication loss
        return (seg.input_byte() & rs4::adapter::kInputProxyRequest) != 0;
      },
      40s));
  ASSERT_TRUE(run_sync());
  EXPECT_EQ(sync.outputs(), FbOutputs{}) << std::hex << sync.outputs().error_number_fb;
  EXPECT_EQ(archive->history({"bus", 4}).value().size(), 1u);
  const auto log = archive->sync_log({"bus", 4}, 10).value();
  ASSERT_EQ(log.size(), 3u);
  EXPECT_EQ(log[2].reason, "background-verify");
  EXPECT_EQ(log[2].outcome, storage::SyncOutcome::kSucceeded);
  EXPECT_TRUE(ossd_after_restart());
}

TEST_F(DeviceSync, ExchangeDownloadsTheStoredSet) {
  auto stored = rs4::scanner::factory_default();
  stored.response_steps = 6;
  stored.pairs[1].protective_mm[100] = 1234;
  ASSERT_TRUE(store(stored, "999"));
  boot(rs4::scanner::factory_default());  // a new device at factory settings
  const auto t0 = seg.now();
  ASSERT_TRUE(run_sync());
  std::printf("download sync: %d records, %lld ms simulated\n", records,
              static_cast<long long>(
                  std::chrono::duration_cast<std::chrono::milliseconds>(seg.now() - t0).count()));
  EXPECT_EQ(sync.outputs(), FbOutputs{})
      << std::hex << sync.outputs().error_number_fb << " rs4 " << sync.outputs().error_number_rs4;
  EXPECT_EQ(seg.device().scanner().transfer_checksum(), rs4::scanner::transfer_checksum(stored));
  EXPECT_TRUE(ossd_after_restart());
  const auto current = archive->current({"bus", 4}).value();
  EXPECT_EQ(current.version.serial_number,
            std::to_string(seg.device().scanner().parameters().identity.serial_number));
}

// rs4sim restarts in the middle of a download: the restored machine fails the sync safely
// (the device rolls back to factory settings and asks again), the retry downloads the set.
TEST_F(DeviceSync, RestartMidDownloadFailsSafelyThenTheRetryDownloads) {
  auto stored = rs4::scanner::factory_default();
  stored.response_steps = 6;
  ASSERT_TRUE(store(stored, "999"));
  boot(rs4::scanner::factory_default());
  ASSERT_TRUE(run_sync(200s, Step::kDownloadCommit));  // every chunk written, no commit
  const auto saved = encode_retentive(sync.snapshot());
  ProxySync restarted{sync_config(), *archive};
  restarted.restore(decode_retentive(saved).value());
  restarted.set_proxy_enable(true);
  ASSERT_TRUE(restarted.ready(seg.now()));
  restarted.start(seg.now());
  for (int i = 0; i < 2000 && restarted.active(); ++i) {
    if (auto req = restarted.take_request(seg.now())) {
      restarted.on_record_result(exchange(*req), seg.now());
    } else {
      seg.run_for(10ms);
      restarted.tick(seg.now());
    }
  }
  EXPECT_EQ(restarted.outputs().error_number_fb, 0x2601);
  EXPECT_TRUE(restarted.outputs().config_set_to_default);
  EXPECT_FALSE(ossd_after_restart());
  EXPECT_NE(seg.device().scanner().transfer_checksum(), rs4::scanner::transfer_checksum(stored));
  // The device asks again (reason retry); after the retry delay the set goes back.
  ASSERT_TRUE(seg.run_until(
      [&] { return (seg.input_byte() & rs4::adapter::kInputProxyRequest) != 0; }, 10s));
  seg.run_for(6s);
  restarted.set_input_byte(seg.input_byte());
  ASSERT_TRUE(restarted.ready(seg.now()));
  restarted.start(seg.now());
  for (int i = 0; i < 20000 && restarted.active(); ++i) {
    restarted.set_input_byte(seg.input_byte());
    if (auto req = restarted.take_request(seg.now())) {
      restarted.on_record_result(exchange(*req), seg.now());
    } else {
      seg.run_for(10ms);
      restarted.tick(seg.now());
    }
  }
  EXPECT_EQ(restarted.outputs(), FbOutputs{}) << std::hex << restarted.outputs().error_number_fb;
  EXPECT_EQ(seg.device().scanner().transfer_checksum(), rs4::scanner::transfer_checksum(stored));
  EXPECT_TRUE(ossd_after_restart());
}

}  // namespace
}  // namespace rs4sim::proxy
