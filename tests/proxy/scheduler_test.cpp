// ProxyScheduler: N syncs at a time per bus, FIFO, progress; ProxyDriver glue
// ([RS4 manual §6.4, §6.5]: serialise the proxies of one bus).
#include "proxy/proxy_driver.h"
#include "proxy/proxy_scheduler.h"
#include "rs4/scanner/parameter_codec.h"
#include "storage/crc32.h"
#include "storage/sqlite_archive.h"
#include "tests/proxy/device_double.h"
#include "tests/storage/archive_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <map>
#include <string>
#include <utility>

namespace rs4sim::proxy::testing {
namespace {

// A bus of device doubles: records are queued and served one per step(), in order.
class Bus final : public RecordChannel {
 public:
  std::map<std::uint8_t, DeviceDouble> devices;
  std::vector<std::uint8_t> begins;  // addresses in the order of their 98 WRITEs
  std::size_t max_running = 0;
  const ProxyScheduler* scheduler = nullptr;
  void submit_write(std::uint8_t address, std::span<const std::uint8_t> record) override {
    if (record.size() > 4 && record[4] == 0x98) begins.push_back(address);
    if (scheduler != nullptr) max_running = std::max(max_running, scheduler->running_count());
    pending_.push_back({address, RecordRequest{RecordWrite{{record.begin(), record.end()}}}});
  }
  void submit_read(std::uint8_t address, std::uint8_t length) override {
    pending_.push_back({address, RecordRequest{RecordRead{length}}});
  }
  // Serves the oldest pending record; false when none.
  bool step(ProxyDriver& driver, dp::TimePoint now) {
    if (pending_.empty()) return false;
    const auto [address, request] = pending_.front();
    pending_.pop_front();
    auto& dev = devices.at(address);
    const auto result = std::holds_alternative<RecordWrite>(request)
                            ? dev.write(std::get<RecordWrite>(request).data)
                            : dev.read(std::get<RecordRead>(request).length);
    driver.on_record_result(address, result, now);
    return true;
  }

 private:
  std::deque<std::pair<std::uint8_t, RecordRequest>> pending_;
};

class SchedulerTest : public ::testing::Test {
 protected:
  void add(std::uint8_t address) {
    bus_.devices[address].serial = 1000u + address;
    bus_.devices[address].factory = true;
    bus_.devices[address].direction = rs4::protocol::SyncDirection::kDownload;
    scheduler_.add(address);
    driver_.set_proxy_enable(address, true);
  }
  // Stores the factory setting as the station's set; returns it.
  std::vector<std::uint8_t> store_factory_set(std::uint8_t address) {
    const auto set = rs4::scanner::encode(rs4::scanner::factory_default());
    storage::StoreRequest r;
    r.station = {"bus1", address};
    r.serial_number = std::to_string(1000 + address);
    r.blob = set;
    r.crc32 = storage::crc32(set);
    EXPECT_TRUE(archive_->store(r));
    return set;
  }
  // One bus cycle: inputs, grants, then every queued record served.
  void cycle() {
    for (auto& [address, dev] : bus_.devices) driver_.on_input_byte(address, dev.input_byte());
    driver_.poll(now_);
    while (bus_.step(driver_, now_)) now_ += std::chrono::microseconds(500);
    now_ += std::chrono::milliseconds(10);
  }
  storage::testing::TempDir dir_;
  std::unique_ptr<storage::SqliteArchive> archive_ =
      storage::SqliteArchive::open(dir_.file("a.sqlite3")).value();
  ProxyScheduler scheduler_{*archive_, {"bus1", 1}};
  Bus bus_;
  ProxyDriver driver_{scheduler_, bus_};
  dp::TimePoint now_{};
};

TEST_F(SchedulerTest, OneSyncAtATimeInRequestOrder) {
  add(5);
  add(4);
  add(6);
  bus_.scheduler = &scheduler_;
  for (int i = 0; i < 100; ++i) cycle();
  // All three asked in the same cycle: queued by address, served one after the other.
  EXPECT_EQ(bus_.begins, (std::vector<std::uint8_t>{4, 5, 6}));
  EXPECT_EQ(bus_.max_running, 1u);
  for (auto& [address, dev] : bus_.devices) EXPECT_TRUE(dev.released) << int{address};
}

TEST_F(SchedulerTest, AnAddressThatAsksAgainQueuesBehindTheOthers) {
  add(4);
  add(5);
  add(6);
  bool again = true;  // 4 asks again right after its sync ended
  bus_.devices[4].answer_hook = [&](std::uint8_t cmd, std::vector<std::uint8_t>&) {
    if (cmd == 0x99 && std::exchange(again, false)) bus_.devices[4].request = true;
  };
  for (int i = 0; i < 100; ++i) cycle();
  EXPECT_EQ(bus_.begins, (std::vector<std::uint8_t>{4, 5, 6, 4}));
}

TEST_F(SchedulerTest, LimitNAllowsNAtOnce) {
  ProxyScheduler two{*archive_, {"bus1", 2}};
  ProxyDriver driver{two, bus_};
  for (const std::uint8_t a : {std::uint8_t{4}, std::uint8_t{5}, std::uint8_t{6}}) {
    bus_.devices[a].direction = rs4::protocol::SyncDirection::kDownload;
    two.add(a);
    driver.set_proxy_enable(a, true);
    driver.on_input_byte(a, bus_.devices[a].input_byte());
  }
  driver.poll(now_);
  EXPECT_EQ(two.running_count(), 2u);
  ASSERT_EQ(two.queue().size(), 1u);
  EXPECT_EQ(two.queue().front(), 6);
  const auto status = two.status();
  EXPECT_TRUE(status[0].running);
  EXPECT_TRUE(status[0].outputs.fb_busy);
  EXPECT_EQ(status[2].queue_position, std::optional<std::size_t>{0});
}

TEST_F(SchedulerTest, ProgressCountsTheDownloadedBytes) {
  const auto set = store_factory_set(4);
  add(4);
  std::size_t last_done = 0;
  bool saw_total = false;
  for (int i = 0; i < 2000; ++i) {
    for (auto& [address, dev] : bus_.devices) driver_.on_input_byte(address, dev.input_byte());
    driver_.poll(now_);
    while (bus_.step(driver_, now_)) {
      const auto p = scheduler_.status()[0].progress;
      if (p.step == Step::kDownloadChunk) {
        EXPECT_EQ(p.bytes_total, set.size());
        EXPECT_GE(p.bytes_done, last_done);
        EXPECT_EQ(p.position, 0x24);
        last_done = p.bytes_done;
        saw_total = true;
      }
    }
    now_ += std::chrono::milliseconds(10);
    if (bus_.devices[4].released) break;
  }
  EXPECT_TRUE(saw_total);
  EXPECT_EQ(last_done, 8u * 1024u);  // before the last chunk's answer
  EXPECT_EQ(bus_.devices[4].set, set);
}

// The retentive record lives in the archive: a scheduler created after a "restart" mid-
// download finds the sync open and fails it safely; the retry then restores the set.
TEST_F(SchedulerTest, RetentiveRecordSurvivesARestartInTheArchive) {
  const auto set = store_factory_set(4);
  add(4);
  bus_.devices[4].set = {0x01, 0x02, 0x03};  // whatever the factory state holds
  for (int i = 0; i < 200; ++i) {
    for (auto& [address, dev] : bus_.devices) driver_.on_input_byte(address, dev.input_byte());
    driver_.poll(now_);
    bool stop = false;
    while (!stop && bus_.step(driver_, now_)) {
      stop = scheduler_.status()[0].progress.step == Step::kDownloadChunk;
    }
    if (stop) break;
    now_ += std::chrono::milliseconds(10);
  }
  const auto saved = archive_->load_proxy_state({"bus1", 4});
  ASSERT_TRUE(saved);
  EXPECT_EQ(saved.value()[1], 0x01);  // sync open

  ASSERT_FALSE(bus_.devices[4].released);
  ASSERT_TRUE(bus_.devices[4].sync_running);
  ProxyScheduler restarted{*archive_, {"bus1", 1}};
  Bus bus;
  bus.devices[4] = bus_.devices[4];  // the device kept running
  ProxyDriver driver{restarted, bus};
  auto& sync = restarted.add(4);
  driver.set_proxy_enable(4, true);
  EXPECT_TRUE(sync.ready(now_));
  for (int i = 0; i < 2000 && !bus.devices[4].released; ++i) {
    driver.on_input_byte(4, bus.devices[4].input_byte());
    driver.poll(now_);
    while (bus.step(driver, now_)) now_ += std::chrono::microseconds(500);
    now_ += std::chrono::milliseconds(10);
  }
  ASSERT_TRUE(bus.devices[4].last_end);
  EXPECT_EQ(bus.devices[4].set, set);  // the retry after the safe abort downloaded it
  EXPECT_TRUE(bus.devices[4].released);
  EXPECT_EQ(sync.outputs(), FbOutputs{});
  EXPECT_EQ(archive_->load_proxy_state({"bus1", 4}).value()[1], 0x00);  // idle again
}

}  // namespace
}  // namespace rs4sim::proxy::testing
