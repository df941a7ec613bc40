#include "rpc/device_target.h"

#include <boost/asio/steady_timer.hpp>

#include <memory>

namespace rs4sim::rpc {

void DeviceTarget::after(dp::Duration delay, std::function<void()> f) {
  auto timer = std::make_shared<boost::asio::steady_timer>(io_, delay);
  timer->async_wait([timer, f = std::move(f)](const boost::system::error_code& ec) {
    if (!ec) f();
  });
}

}  // namespace rs4sim::rpc
