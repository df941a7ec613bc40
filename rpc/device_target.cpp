#include "rpc/device_target.h"

#include "rpc/rs4_state.h"

#include <boost/asio/steady_timer.hpp>

#include <memory>

namespace rs4sim::rpc {
namespace {

// Polls the hub every period until `stopped` (the timer lives in its own handler).
void poll_every(const std::shared_ptr<boost::asio::steady_timer>& timer,
                std::shared_ptr<EventHub> hub, const dp::Clock& clock,
                std::shared_ptr<bool> stopped) {
  timer->expires_after(DeviceTarget::kPollPeriod);
  timer->async_wait([timer, hub = std::move(hub), &clock,
                     stopped = std::move(stopped)](const boost::system::error_code& ec) {
    if (ec || *stopped) return;
    hub->poll(clock.now());
    poll_every(timer, hub, clock, stopped);
  });
}

}  // namespace

DeviceTarget::DeviceTarget(std::vector<Station> stations, const dp::Clock& clock,
                           boost::asio::io_context& io)
    : stations_(std::move(stations)), clock_(clock), io_(io) {
  for (const Station& s : stations_) hub_->watch(s.address, *s.device);
  const auto timer = std::make_shared<boost::asio::steady_timer>(io);
  poll_timer_ = timer;
  poll_every(timer, hub_, clock, stopped_);
}

std::vector<std::uint8_t> DeviceTarget::addresses() const {
  std::vector<std::uint8_t> out;
  out.reserve(stations_.size());
  for (const Station& s : stations_) out.push_back(s.address);
  return out;
}

rs4::device::Rs4Device* DeviceTarget::device(std::uint8_t address) {
  for (const Station& s : stations_) {
    if (s.address == address) return s.device;
  }
  return nullptr;
}

// On the loop's thread: a handler already queued sees the flag, a pending wait is cancelled.
void DeviceTarget::stop() {
  *stopped_ = true;
  if (const auto timer = poll_timer_.lock()) timer->cancel();
}

LineDeviceTarget::LineDeviceTarget(stream::DeviceKind kind, std::unique_ptr<Watcher> watcher,
                                   const dp::Clock& clock, boost::asio::io_context& io)
    : kind_(kind), address_(watcher->address()), clock_(clock) {
  hub_->watch(std::move(watcher));
  const auto timer = std::make_shared<boost::asio::steady_timer>(io);
  poll_timer_ = timer;
  poll_every(timer, hub_, clock, stopped_);
}

void LineDeviceTarget::stop() {
  *stopped_ = true;
  if (const auto timer = poll_timer_.lock()) timer->cancel();
}

void DeviceTarget::after(dp::Duration delay, std::function<void()> f) {
  auto timer = std::make_shared<boost::asio::steady_timer>(io_, delay);
  timer->async_wait([timer, f = std::move(f)](const boost::system::error_code& ec) {
    if (!ec) f();
  });
}

bool DeviceTarget::link_timing(std::uint8_t address, v1::LinkTiming& out) {
  const dp::link::TurnaroundStats* stats = turnaround_ ? turnaround_(address) : nullptr;
  if (stats == nullptr) return false;
  fill_link_timing(*stats, slot_time_us_, out);
  return true;
}

}  // namespace rs4sim::rpc
