// SyncHarness and FaultyArchive.
#include "tests/proxy/sync_harness.h"

#include "rs4/scanner/parameter_codec.h"
#include "storage/crc32.h"

#include <algorithm>

namespace rs4sim::proxy::testing {

namespace {
storage::ArchiveFailure injected() {
  return storage::archive_error(storage::ArchiveError::kIo, "injected failure");
}
}  // namespace

storage::Result<storage::VersionInfo> FaultyArchive::store(const storage::StoreRequest& r) {
  if (fail == Op::kStore) return injected();
  return inner_.store(r);
}
storage::Result<storage::VersionWithSet> FaultyArchive::current(const storage::StationKey& s) {
  if (fail == Op::kCurrent) return injected();
  return inner_.current(s);
}
storage::Result<storage::VersionWithSet> FaultyArchive::get(storage::VersionId v) {
  if (fail == Op::kGet) return injected();
  return inner_.get(v);
}
storage::Result<void> FaultyArchive::mark_downloaded(storage::VersionId v) {
  if (fail == Op::kMarkDownloaded) return injected();
  return inner_.mark_downloaded(v);
}
storage::Result<void> FaultyArchive::log_sync(const storage::SyncLogEntry& e) {
  if (fail == Op::kLogSync) return injected();
  return inner_.log_sync(e);
}

SyncHarness::SyncHarness()
    : real(storage::SqliteArchive::open(dir.file("archive.sqlite3")).value()), archive(*real) {
  config.station = kStation;
  sync = std::make_unique<ProxySync>(config, archive);
}

std::vector<std::uint8_t> SyncHarness::custom_set(std::uint8_t response_steps) {
  auto set = rs4::scanner::factory_default();
  set.response_steps = response_steps;
  return rs4::scanner::encode(set);
}

storage::VersionInfo SyncHarness::store(const std::vector<std::uint8_t>& blob,
                                        const std::string& serial) {
  storage::StoreRequest r;
  r.station = kStation;
  r.device_type = "0x0504";
  r.serial_number = serial;
  r.blob = blob;
  r.crc32 = storage::crc32(blob);
  r.summary = "test";
  return real->store(r).value();
}

bool SyncHarness::run_sync(std::optional<Step> stop_at) {
  sync->set_input_byte(device.input_byte());
  sync->set_proxy_enable(enable);
  if (!sync->ready(now)) return false;
  sync->start(now);
  return resume(stop_at);
}

bool SyncHarness::resume(std::optional<Step> stop_at) {
  for (int i = 0; i < 200000; ++i) {
    sync->set_input_byte(device.input_byte());
    if (stop_at && sync->progress().step == *stop_at) return true;
    auto request = sync->take_request(now);
    if (!request) {
      if (!sync->active()) return true;
      const auto wake = sync->next_wakeup();
      if (!wake) return false;  // stuck
      now = std::max(now, *wake);
      sync->tick(now);
      continue;
    }
    const auto step = sync->progress().step;
    issued.push_back({step, *request});
    const auto result = serve(*request, step);
    now += std::chrono::milliseconds(1);
    sync->on_record_result(result, now);
  }
  return false;
}

RecordResult SyncHarness::serve(const RecordRequest& request, Step step) {
  const bool here = inject && !injected_ && inject->step == step;
  if (const auto* write = std::get_if<RecordWrite>(&request)) {
    if (here && inject->kind == FailureKind::kWrite) {
      injected_ = true;
      return RecordResult::negative(kWriteRefusedCode1, 0x00);
    }
    return device.write(write->data);
  }
  const auto length = std::get<RecordRead>(request).length;
  if (here && inject->kind == FailureKind::kRead) {
    injected_ = true;
    return RecordResult::negative(kReadRefusedCode1, 0x00);
  }
  if (here && inject->kind == FailureKind::kBadRecord) {
    injected_ = true;
    return corrupt_read(length);
  }
  return device.read(length);
}

// Reads the device's whole answer and returns its first byte alone as the answer: a record
// of the right command that no decoder accepts.
RecordResult SyncHarness::corrupt_read(std::uint8_t length) {
  std::optional<std::uint8_t> code;
  for (int i = 0; i < 64; ++i) {
    const auto r = device.read(length);
    const auto block = rs4::protocol::decode_block(r.data, rs4::protocol::Direction::kRead);
    if (!block) break;
    if (!code && !block.value().payload.empty()) code = block.value().payload[0];
    if (code && block.value().header.is_last()) break;
  }
  std::vector<std::uint8_t> record;
  const std::uint8_t payload[] = {code.value_or(0x00)};
  (void)rs4::protocol::encode_block(0x31, rs4::protocol::kLastBlockNumber, payload, record);
  return RecordResult::success(std::move(record));
}

}  // namespace rs4sim::proxy::testing
