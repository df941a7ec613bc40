#pragma once
// One steady_timer armed for the earliest deadline of a runner's cores (dp::Station,
// stream::ByteDevice): re-arming for the same deadline is a no-op, nullopt disarms, and
// `fire` runs on the loop once the deadline has passed on the runner's clock.

#include "stream/clock.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include <functional>
#include <optional>

namespace rs4sim::stream {

// The earliest next_deadline() of `cores` (pointers to dp::Station or stream::ByteDevice).
template <class Cores>
[[nodiscard]] std::optional<TimePoint> earliest_deadline(const Cores& cores) {
  std::optional<TimePoint> earliest;
  for (const auto* core : cores) {
    const auto d = core->next_deadline();
    if (d && (!earliest || *d < *earliest)) earliest = d;
  }
  return earliest;
}

class DeadlineTimer {
 public:
  explicit DeadlineTimer(boost::asio::io_context& io) : timer_(io) {}

  void arm(std::optional<TimePoint> earliest, const Clock& clock, std::function<void()> fire);
  void cancel();
  [[nodiscard]] boost::asio::any_io_executor executor() { return timer_.get_executor(); }

 private:
  boost::asio::steady_timer timer_;
  std::optional<TimePoint> armed_for_;
};

}  // namespace rs4sim::stream
