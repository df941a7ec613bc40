#include "rpc/device_watcher.h"

#include "rpc/rs4_state.h"

#include <cstdio>

namespace rs4sim::rpc {
namespace {

// The names of Look::items, in order (the StateChange.what of docs/rpc.md).
constexpr std::array<const char*, 12> kWhat = {
    "powered",    "dp-state",    "fdevice-state", "rs4-state", "led",  "ossd", "field-pair",
    "proxy-phase", "input-byte", "output-byte",   "led3",      "led5"};

std::string hex2(std::uint8_t b) {
  char s[3];
  std::snprintf(s, sizeof s, "%02x", b);
  return s;
}

}  // namespace

DeviceWatcher::Look DeviceWatcher::look() const {
  const auto view = device_.adapter().view();
  const auto status = device_.scanner().status();
  const auto& slave = device_.slave();
  const auto leds = device_.scanner().leds();
  Look l;
  l.items = {device_.powered() ? "on" : "off",
             dp::slave::to_string(slave.state()),
             std::string(profisafe::to_token(view.fdevice)),
             rs4::scanner::to_string(status.state),
             std::string(rs4::adapter::to_token(view.led)),
             view.input.ossd ? "on" : "off",
             std::to_string(status.first_pair),
             std::string(rs4::adapter::to_token(view.proxy)),
             hex2(view.input_byte),
             hex2(view.output_byte),
             leds.led3_red ? "red" : "off",
             leds.led5_yellow_blinking ? "yellow-blinking" : "off"};
  l.alarms_pending = static_cast<std::uint32_t>(slave.alarms().pending());
  l.alarms_outstanding = static_cast<std::uint32_t>(slave.alarms().outstanding());
  l.error_active = view.error_active;
  const auto diag = slave.diagnosis();
  l.diagnosis.assign(diag.begin(), diag.end());
  return l;
}

v1::Event DeviceWatcher::event(std::int64_t now_ns) const {
  v1::Event e;
  e.set_address(address_);
  e.set_now_ns(now_ns);
  return e;
}

void DeviceWatcher::report(const Look& now, std::int64_t now_ns, bool initial,
                           const Sink& sink) const {
  for (std::size_t i = 0; i < kItems; ++i) {
    if (!initial && now.items[i] == last_.items[i]) continue;
    auto e = event(now_ns);
    auto* change = e.mutable_state();
    change->set_what(kWhat[i]);
    if (!initial) change->set_previous(last_.items[i]);
    change->set_to(now.items[i]);
    sink(std::move(e));
  }
  if (initial || now.alarms_pending != last_.alarms_pending ||
      now.alarms_outstanding != last_.alarms_outstanding ||
      now.error_active != last_.error_active) {
    auto e = event(now_ns);
    e.mutable_alarm()->set_pending(now.alarms_pending);
    e.mutable_alarm()->set_outstanding(now.alarms_outstanding);
    e.mutable_alarm()->set_error_active(now.error_active);
    sink(std::move(e));
  }
  if (initial || now.diagnosis != last_.diagnosis) {
    auto e = event(now_ns);
    e.mutable_diagnosis()->set_bytes(std::string(now.diagnosis.begin(), now.diagnosis.end()));
    sink(std::move(e));
  }
}

void DeviceWatcher::poll(std::int64_t now_ns, const Sink& sink) {
  auto now = look();
  report(now, now_ns, false, sink);
  last_ = std::move(now);
}

void DeviceWatcher::snapshot(std::int64_t now_ns, const Sink& sink) const {
  report(last_, now_ns, true, sink);
}

}  // namespace rs4sim::rpc
