#include "rpc/items_watcher.h"

#include <chrono>

namespace rs4sim::rpc {

v1::Event ItemsWatcher::change(std::int64_t now_ns, const std::string& what,
                               const std::string& from, const std::string& to) const {
  v1::Event e;
  e.set_address(address_);
  e.set_now_ns(now_ns);
  auto* c = e.mutable_state();
  c->set_what(what);
  c->set_previous(from);
  c->set_to(to);
  return e;
}

void ItemsWatcher::poll(std::int64_t now_ns, const Sink& sink) {
  const dp::TimePoint now{
      std::chrono::duration_cast<dp::Duration>(std::chrono::nanoseconds(now_ns))};
  auto items = look_(now);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string before = i < last_.size() ? last_[i].second : std::string();
    if (i < last_.size() && before == items[i].second) continue;
    sink(change(now_ns, items[i].first, before, items[i].second));
  }
  last_ = std::move(items);
}

void ItemsWatcher::snapshot(std::int64_t now_ns, const Sink& sink) const {
  for (const auto& [what, value] : last_) sink(change(now_ns, what, "", value));
}

}  // namespace rs4sim::rpc
