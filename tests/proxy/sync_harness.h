#pragma once
// Drives one ProxySync against a DeviceDouble on the manual clock, with a real SqliteArchive
// in a temporary file behind a FaultyArchive, and failures injected at a chosen step.

#include "proxy/proxy_sync.h"
#include "storage/sqlite_archive.h"
#include "tests/proxy/device_double.h"
#include "tests/storage/archive_test_support.h"

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rs4sim::proxy::testing {

// Delegates to a real archive; the chosen operation fails (kIo) while `fail` names it.
class FaultyArchive final : public storage::ParameterArchive {
 public:
  enum class Op : std::uint8_t { kNone, kCurrent, kStore, kGet, kMarkDownloaded, kLogSync };
  explicit FaultyArchive(storage::ParameterArchive& inner) : inner_(inner) {}
  Op fail = Op::kNone;

  storage::Result<storage::VersionInfo> store(const storage::StoreRequest& r) override;
  storage::Result<storage::VersionWithSet> current(const storage::StationKey& s) override;
  storage::Result<std::vector<storage::VersionInfo>> history(
      const storage::StationKey& s) override {
    return inner_.history(s);
  }
  storage::Result<storage::VersionWithSet> get(storage::VersionId v) override;
  using storage::ParameterArchive::restore;
  storage::Result<storage::VersionInfo> restore(storage::VersionId v, storage::Timestamp at,
                                                std::string note,
                                                const storage::Author& by) override {
    return inner_.restore(v, at, std::move(note), by);
  }
  storage::Result<void> mark_downloaded(storage::VersionId v) override;
  storage::Result<storage::VersionInfo> annotate(storage::VersionId v, std::string note) override {
    return inner_.annotate(v, std::move(note));
  }
  storage::Result<std::vector<storage::VersionInfo>> versions_after(storage::VersionId after,
                                                                    std::size_t limit) override {
    return inner_.versions_after(after, limit);
  }
  storage::Result<storage::VersionId> newest_version_id() override {
    return inner_.newest_version_id();
  }
  storage::Result<std::vector<storage::StationInfo>> stations() override {
    return inner_.stations();
  }
  storage::Result<void> log_sync(const storage::SyncLogEntry& e) override;
  storage::Result<std::vector<storage::SyncLogEntry>> sync_log(const storage::StationKey& s,
                                                               std::size_t limit) override {
    return inner_.sync_log(s, limit);
  }
  storage::Result<void> save_proxy_state(const storage::StationKey& s,
                                         std::span<const std::uint8_t> state,
                                         storage::Timestamp at) override {
    return inner_.save_proxy_state(s, state, at);
  }
  storage::Result<std::vector<std::uint8_t>> load_proxy_state(
      const storage::StationKey& s) override {
    return inner_.load_proxy_state(s);
  }
  storage::Result<storage::IntegrityReport> check_integrity() override {
    return inner_.check_integrity();
  }
  storage::Result<storage::Snapshot> export_snapshot(storage::Timestamp at) override {
    return inner_.export_snapshot(at);
  }
  storage::Result<storage::ImportSummary> import_snapshot(
      const storage::Snapshot& s, const storage::ImportOptions& o) override {
    return inner_.import_snapshot(s, o);
  }

 private:
  storage::ParameterArchive& inner_;
};

struct Injection {
  Step step = Step::kIdle;
  FailureKind kind = FailureKind::kWrite;
};

// One record as the machine issued it.
struct IssuedRecord {
  Step step = Step::kIdle;
  RecordRequest request;
};

inline constexpr std::uint8_t kWriteRefusedCode1 = 0xB5;  // state conflict
inline constexpr std::uint8_t kReadRefusedCode1 = 0xA0;   // read error

class SyncHarness {
 public:
  SyncHarness();

  static inline const storage::StationKey kStation{"bus1", 4};

  // A set in transfer form that differs from the factory setting by `response_steps`.
  static std::vector<std::uint8_t> custom_set(std::uint8_t response_steps);
  // Stores `blob` for the station as if uploaded from a device with `serial`.
  storage::VersionInfo store(const std::vector<std::uint8_t>& blob, const std::string& serial);

  // Starts a sync when the machine is ready and runs it (and its failure report and
  // background verify) to the end. False when it did not start or got stuck.
  bool run_sync(std::optional<Step> stop_at = std::nullopt);
  // Goes on with the sync run_sync(stop_at) stopped in (its first record not yet issued).
  bool resume(std::optional<Step> stop_at = std::nullopt);
  // Advances the clock.
  void advance(dp::Duration d) { now += d; }
  // custom_set(3) stored from serial "1001", and a device on factory settings that asks for a
  // download: where the download scenarios start. Returns the stored set.
  std::vector<std::uint8_t> store_for_a_factory_device() {
    auto set = custom_set(3);
    store(set, "1001");
    device.factory = true;
    device.direction = rs4::protocol::SyncDirection::kDownload;
    return set;
  }
  // custom_set(3) stored from serial "1001" and held by the device too. Returns the set.
  std::vector<std::uint8_t> store_the_devices_set() {
    auto set = custom_set(3);
    store(set, "1001");
    device.set = set;
    return set;
  }
  // The device asks to upload its own `set`, changed for `reason`.
  void device_changed_to(std::vector<std::uint8_t> set, rs4::protocol::SyncReason reason) {
    device.set = std::move(set);
    device.reason = reason;
    device.direction = rs4::protocol::SyncDirection::kUpload;
  }
  // After a failed sync: the retry, config.retry_delay later, downloads `set` completely and
  // releases the device.
  void expect_retry_restores(const std::vector<std::uint8_t>& set) {
    advance(config.retry_delay);
    ASSERT_TRUE(run_sync());
    EXPECT_EQ(sync->outputs(), FbOutputs{});
    EXPECT_EQ(device.set, set);
    EXPECT_TRUE(device.released);
  }

  storage::testing::TempDir dir;
  std::unique_ptr<storage::SqliteArchive> real;
  FaultyArchive archive;
  DeviceDouble device;
  ProxySyncConfig config;
  std::unique_ptr<ProxySync> sync;
  dp::TimePoint now{};
  std::optional<Injection> inject;
  std::vector<IssuedRecord> issued;
  bool enable = true;

 private:
  RecordResult serve(const RecordRequest& request, Step step);
  RecordResult corrupt_read(std::uint8_t length);
  bool injected_ = false;
};

}  // namespace rs4sim::proxy::testing
