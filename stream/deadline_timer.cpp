#include "stream/deadline_timer.h"

#include <boost/asio/error.hpp>

#include <algorithm>

namespace rs4sim::stream {

void DeadlineTimer::arm(std::optional<TimePoint> earliest, const Clock& clock,
                        std::function<void()> fire) {
  if (earliest == armed_for_) return;
  armed_for_ = earliest;
  if (!earliest) {
    timer_.cancel();
    return;
  }
  const Duration delay = std::max(Duration::zero(), *earliest - clock.now());
  timer_.expires_after(delay);
  timer_.async_wait([this, fire = std::move(fire)](const boost::system::error_code& ec) {
    if (ec == boost::asio::error::operation_aborted) return;
    armed_for_.reset();
    fire();
  });
}

void DeadlineTimer::cancel() {
  armed_for_.reset();
  timer_.cancel();
}

}  // namespace rs4sim::stream
