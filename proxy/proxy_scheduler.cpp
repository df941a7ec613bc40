// ProxyScheduler: N syncs at a time per bus, FIFO ([RS4 manual §6.4, §6.5]).
#include "proxy/proxy_scheduler.h"

#include <algorithm>

namespace rs4sim::proxy {

ProxyScheduler::ProxyScheduler(storage::ParameterArchive& archive, SchedulerConfig config)
    : archive_(archive), config_(std::move(config)) {
  config_.max_parallel = std::max<std::size_t>(config_.max_parallel, 1);
}

ProxySync& ProxyScheduler::add(std::uint8_t address, ProxySyncConfig config) {
  config.station = storage::StationKey{config_.bus, address};
  config.wall_clock = config_.wall_clock;
  config.simulated = config_.simulated;
  config.recording = config_.recording;
  std::erase(queue_, address);
  saved_.erase(address);
  auto& slot = syncs_[address];
  slot = std::make_unique<ProxySync>(std::move(config), archive_);
  if (config_.persist) {
    const auto bytes = archive_.load_proxy_state(slot->station());
    if (bytes) {
      const auto record = decode_retentive(bytes.value());
      slot->restore(record ? *record : RetentiveRecord{RetentiveState::kSyncOpen});
    } else if (bytes.error().code != storage::ArchiveError::kNotFound) {
      slot->restore(RetentiveRecord{RetentiveState::kSyncOpen});
    }
  }
  return *slot;
}

bool ProxyScheduler::persist(std::uint8_t address, dp::TimePoint now) {
  const auto* sync = find(address);
  if (!config_.persist || sync == nullptr) return true;
  const auto bytes = encode_retentive(sync->snapshot());
  const auto it = saved_.find(address);
  if (it != saved_.end() && it->second == bytes) return true;
  if (!archive_.save_proxy_state(sync->station(), bytes, wall_time(sync->config(), now))) {
    return false;
  }
  saved_[address] = bytes;
  return true;
}

ProxySync* ProxyScheduler::find(std::uint8_t address) noexcept {
  const auto it = syncs_.find(address);
  return it == syncs_.end() ? nullptr : it->second.get();
}

std::vector<std::uint8_t> ProxyScheduler::addresses() const {
  std::vector<std::uint8_t> out;
  for (const auto& [address, sync] : syncs_) out.push_back(address);
  return out;
}

std::size_t ProxyScheduler::running_count() const noexcept {
  return static_cast<std::size_t>(std::count_if(
      syncs_.begin(), syncs_.end(), [](const auto& entry) { return entry.second->active(); }));
}

void ProxyScheduler::poll(dp::TimePoint now) {
  std::erase_if(queue_, [&](std::uint8_t address) {
    const auto* sync = find(address);
    return sync == nullptr || !sync->ready(now);
  });
  for (const auto& [address, sync] : syncs_) {
    if (sync->ready(now) && std::find(queue_.begin(), queue_.end(), address) == queue_.end())
      queue_.push_back(address);
  }
  while (!queue_.empty() && running_count() < config_.max_parallel) {
    const auto address = queue_.front();
    queue_.pop_front();
    syncs_.at(address)->start(now);
  }
}

std::vector<StationStatus> ProxyScheduler::status() const {
  std::vector<StationStatus> out;
  for (const auto& [address, sync] : syncs_) {
    StationStatus s;
    s.address = address;
    s.running = sync->active();
    const auto it = std::find(queue_.begin(), queue_.end(), address);
    if (it != queue_.end()) s.queue_position = static_cast<std::size_t>(it - queue_.begin());
    s.progress = sync->progress();
    s.outputs = sync->outputs();
    out.push_back(s);
  }
  return out;
}

std::optional<dp::TimePoint> ProxyScheduler::next_wakeup() const noexcept {
  std::optional<dp::TimePoint> next;
  for (const auto& [address, sync] : syncs_) {
    const auto t = sync->next_wakeup();
    if (t && (!next || *t < *next)) next = t;
  }
  return next;
}

}  // namespace rs4sim::proxy
