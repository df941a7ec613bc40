#pragma once
// The event source of a run (docs/rpc.md "Event stream"): the watched devices and the
// streams' queues. The loop thread produces: poll() after bus activity or on a timer,
// telegram() for every telegram the link carries; each event goes to the queues that watch
// its station. Streams subscribe on the loop (through the Executor) so that their first
// events, the snapshot, line up with the changes that follow; they unsubscribe from their
// own thread.

#include "dp/time/clock.h"
#include "rpc/device_watcher.h"
#include "rpc/event_queue.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

namespace rs4sim::rpc {

class EventHub {
 public:
  EventHub() = default;
  EventHub(const EventHub&) = delete;
  EventHub& operator=(const EventHub&) = delete;
  ~EventHub();

  // Setup, before the run: a device to watch.
  void watch(std::uint8_t address, const rs4::device::Rs4Device& device);
  void watch(std::unique_ptr<Watcher> watcher);
  [[nodiscard]] bool watches(std::uint8_t address) const;

  // ---- loop thread ------------------------------------------------------------------------
  void poll(dp::TimePoint now);
  // True when a stream wants telegrams (the caller skips building them otherwise).
  [[nodiscard]] bool wants_telegrams() const noexcept { return telegram_streams_.load() != 0; }
  void telegram(std::uint8_t address, v1::Direction direction, std::span<const std::uint8_t> wire,
                const char* fate, dp::TimePoint now);
  // Adds a stream and gives it the snapshot of its stations.
  void subscribe(const std::shared_ptr<EventQueue>& queue, dp::TimePoint now);

  // ---- any thread ----------------------------------------------------------------------------
  void unsubscribe(const std::shared_ptr<EventQueue>& queue);
  // Ends every stream (the run stops).
  void close();

 private:
  void publish(v1::Event&& e, bool is_telegram);

  std::vector<std::unique_ptr<Watcher>> watchers_;
  std::mutex mutex_;  // guards queues_ (unsubscribe comes from a stream's thread)
  std::vector<std::shared_ptr<EventQueue>> queues_;
  std::atomic<int> telegram_streams_{0};
  std::atomic<int> streams_{0};
};

}  // namespace rs4sim::rpc
