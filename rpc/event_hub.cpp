#include "rpc/event_hub.h"

#include "rpc/service_support.h"

#include <algorithm>

namespace rs4sim::rpc {

EventHub::~EventHub() { close(); }

void EventHub::watch(std::uint8_t address, const rs4::device::Rs4Device& device) {
  watchers_.push_back(std::make_unique<DeviceWatcher>(address, device));
}

void EventHub::watch(std::unique_ptr<Watcher> watcher) { watchers_.push_back(std::move(watcher)); }

bool EventHub::watches(std::uint8_t address) const {
  return std::any_of(watchers_.begin(), watchers_.end(),
                     [address](const auto& w) { return w->address() == address; });
}

void EventHub::poll(dp::TimePoint now) {
  if (streams_.load() == 0) return;  // nobody listens: the next subscribe() looks afresh
  const auto ns = to_ns(now);
  for (auto& w : watchers_) w->poll(ns, [this](v1::Event&& e) { publish(std::move(e), false); });
}

void EventHub::telegram(std::uint8_t address, v1::Direction direction,
                        std::span<const std::uint8_t> wire, const char* fate, dp::TimePoint now) {
  v1::Event e;
  e.set_address(address);
  e.set_now_ns(to_ns(now));
  auto* t = e.mutable_telegram();
  t->set_direction(direction);
  t->set_frame(std::string(wire.begin(), wire.end()));
  t->set_fate(fate);
  publish(std::move(e), true);
}

void EventHub::subscribe(const std::shared_ptr<EventQueue>& queue, dp::TimePoint now) {
  const auto ns = to_ns(now);
  // Bring the look up to date for the streams already there, then snapshot it for this one.
  for (auto& w : watchers_) w->poll(ns, [this](v1::Event&& e) { publish(std::move(e), false); });
  for (const auto& w : watchers_) {
    if (!queue->watches(w->address())) continue;
    w->snapshot(ns, [&queue](v1::Event&& e) { queue->push(std::move(e)); });
  }
  const std::lock_guard lock(mutex_);
  queues_.push_back(queue);
  streams_.fetch_add(1);
  if (queue->telegrams()) telegram_streams_.fetch_add(1);
}

void EventHub::unsubscribe(const std::shared_ptr<EventQueue>& queue) {
  const std::lock_guard lock(mutex_);
  const auto it = std::find(queues_.begin(), queues_.end(), queue);
  if (it == queues_.end()) return;
  queues_.erase(it);
  streams_.fetch_sub(1);
  if (queue->telegrams()) telegram_streams_.fetch_sub(1);
}

void EventHub::close() {
  const std::lock_guard lock(mutex_);
  for (const auto& q : queues_) q->close();
  queues_.clear();
  streams_.store(0);
  telegram_streams_.store(0);
}

void EventHub::publish(v1::Event&& e, bool is_telegram) {
  const std::lock_guard lock(mutex_);
  const auto address = static_cast<std::uint8_t>(e.address());
  std::size_t matching = 0;
  for (const auto& q : queues_) {
    if ((!is_telegram || q->telegrams()) && q->watches(address)) ++matching;
  }
  for (const auto& q : queues_) {
    if ((is_telegram && !q->telegrams()) || !q->watches(address)) continue;
    if (--matching == 0) {
      q->push(std::move(e));  // the last one takes it: no copy for a single stream
    } else {
      q->push(e);
    }
  }
}

}  // namespace rs4sim::rpc
