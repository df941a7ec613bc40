#include "stream/coalesced_wake.h"

#include <boost/asio/post.hpp>

namespace rs4sim::stream {

CoalescedWake::CoalescedWake(boost::asio::any_io_executor executor, std::function<void()> on_wake)
    : state_(std::make_shared<State>(State{std::move(executor), std::move(on_wake)})) {}

std::function<void()> CoalescedWake::handler() const {
  return [weak = std::weak_ptr(state_)] { wake(weak); };
}

void CoalescedWake::wake(const std::weak_ptr<State>& weak) {
  const auto state = weak.lock();
  if (!state || !state->enabled || state->posted) return;
  state->posted = true;
  boost::asio::post(state->executor, [weak] {
    const auto s = weak.lock();
    if (!s) return;
    s->posted = false;
    if (s->enabled) s->on_wake();
  });
}

}  // namespace rs4sim::stream
