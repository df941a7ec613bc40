#pragma once
// ProxyScheduler: the ProxySync machines of one bus, at most N syncs at a time (default 1:
// [RS4 manual §6.4, §6.5] advise serialising the proxies of one bus), granted in the order the
// slaves asked (a fair FIFO queue; a slave that asks again queues behind the others).
// Progress per slave for the CLI and the RPC (docs/proxy.md "Scheduler").

#include "proxy/proxy_sync.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::proxy {

struct SchedulerConfig {
  std::string bus = "bus";            // the archive's StationKey::bus
  std::size_t max_parallel = 1;       // N; 0 is taken as 1
  WallClock wall_clock{};             // ProxySyncConfig::wall_clock for every slave
  bool simulated = false;             // ProxySyncConfig::simulated for every slave
  // Keep each slave's retentive record in the archive (save_proxy_state): loaded by add(),
  // saved by persist() whenever it changed (docs/proxy.md "Retentive record").
  bool persist = true;
  Recording recording{};  // ProxySyncConfig::recording for every slave
};

struct StationStatus {
  std::uint8_t address = 0;
  bool running = false;
  std::optional<std::size_t> queue_position;  // 0 = next
  SyncProgress progress;
  FbOutputs outputs;
  friend bool operator==(const StationStatus&, const StationStatus&) = default;
};

class ProxyScheduler {
 public:
  ProxyScheduler(storage::ParameterArchive& archive, SchedulerConfig config = {});

  // The station key (bus, address), wall clock and `simulated` are set by the scheduler. Replaces an
  // existing one. With `persist`, the retentive record saved for the station is restored; one
  // that cannot be read or decoded is restored as an open sync (the safe side).
  ProxySync& add(std::uint8_t address, ProxySyncConfig config = {});
  // Saves the slave's retentive record if it changed since the last save. False when the
  // archive refused it (it is tried again at the next call).
  bool persist(std::uint8_t address, dp::TimePoint now);
  [[nodiscard]] ProxySync* find(std::uint8_t address) noexcept;
  // The wall clock of the syncs added from now on (an owner that learns its clock only when
  // the run starts).
  void set_wall_clock(WallClock clock) { config_.wall_clock = std::move(clock); }
  [[nodiscard]] std::vector<std::uint8_t> addresses() const;

  // Queues the slaves that became ready, drops the ones that no longer are, and starts
  // queued ones while fewer than N run.
  void poll(dp::TimePoint now);

  [[nodiscard]] std::size_t running_count() const noexcept;
  [[nodiscard]] const std::deque<std::uint8_t>& queue() const noexcept { return queue_; }
  [[nodiscard]] std::vector<StationStatus> status() const;
  [[nodiscard]] std::optional<dp::TimePoint> next_wakeup() const noexcept;

 private:
  storage::ParameterArchive& archive_;
  SchedulerConfig config_;
  std::map<std::uint8_t, std::unique_ptr<ProxySync>> syncs_;
  std::deque<std::uint8_t> queue_;
  std::map<std::uint8_t, std::array<std::uint8_t, kRetentiveSize>> saved_;
};

}  // namespace rs4sim::proxy
