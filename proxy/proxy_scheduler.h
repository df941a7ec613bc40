#pragma once
// ProxyScheduler: the ProxySync machines of one bus, at most N syncs at a time (default 1:
// [RS4 manual §6.5] advises serialising the proxies of one bus), granted in the order the
// slaves asked (a fair FIFO queue; a slave that asks again queues behind the others).
// Progress per slave for the CLI and the RPC (docs/proxy.md "Scheduler").

#include "proxy/proxy_sync.h"

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
  std::string bus = "bus";       // the archive's StationKey::bus
  std::size_t max_parallel = 1;  // N; 0 is taken as 1
};

struct StationStatus {
  std::uint8_t address = 0;
  bool running = false;
  std::optional<std::size_t> queue_position;  // 0 = next
  SyncProgress progress;
  FbOutputs outputs;
};

class ProxyScheduler {
 public:
  ProxyScheduler(storage::ParameterArchive& archive, SchedulerConfig config = {});

  // The station key (bus, address) is set by the scheduler. Replaces an existing one.
  ProxySync& add(std::uint8_t address, ProxySyncConfig config = {});
  [[nodiscard]] ProxySync* find(std::uint8_t address) noexcept;
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
};

}  // namespace rs4sim::proxy
