#include "rs4/device/rs4_device.h"

#include "rs4/adapter/rs4_gsd.h"

namespace rs4sim::rs4::device {

namespace {

adapter::AdapterConfig adapter_config(const Rs4DeviceConfig& c) {
  adapter::AdapterConfig a = c.adapter;
  a.scanner = c.scanner;
  a.scanner.boot_duration = c.boot_time;
  a.switches = c.switches;
  a.init_duration = c.adapter_init;
  a.reset_link_down = c.reset_link_down;
  return a;
}

}  // namespace

dp::slave::Config rs4_slave_config(std::uint8_t address) { return adapter::slave_config(address); }

namespace {

// The slave's address before the switches were ever read valid: the factory setting
// ([RS4 manual §4.5]). The station is silent while the switches are invalid (on_bus()), so this
// address is only what address() reports, never one the station answers at.
std::uint8_t initial_address(const Rs4DeviceConfig& c) {
  const auto addr = adapter::station_address(c.switches);
  return addr ? addr.value() : adapter::station_address(Rs4DeviceConfig{}.switches).value();
}

}  // namespace

Rs4Device::Rs4Device(const Rs4DeviceConfig& config)
    : unit_(config.scanner),
      adapter_(adapter_config(config)),
      slave_(config.adapter.gsd ? config.adapter.gsd->slave_at(initial_address(config))
                                : rs4_slave_config(initial_address(config)),
             adapter_) {
  slave_.set_wake_handler([this] { wake(); });  // the slave's wake-ups are the device's
}

// The one dp::slave::Slave back in Wait_Prm at `address` (power-up, link return); the adapter's
// SlaveControl reference stays valid.
void Rs4Device::restart_slave(std::uint8_t address) { slave_.restart(address); }

void Rs4Device::power_on(TimePoint now) {
  if (powered_) return;
  powered_ = true;
  link_down_ = false;
  pending_.clear();
  ++counters_.power_ups;
  adapter_.power_on(now);  // reads the address switches ([RS4 manual §4.5])
  const auto addr = adapter_.station_address();
  restart_slave(addr ? *addr : slave_.address());
  wake();
}

void Rs4Device::power_off(TimePoint now) {
  powered_ = false;
  link_down_ = false;
  pending_.clear();
  adapter_.power_off(now);
  wake();
}

void Rs4Device::power_cycle(TimePoint now) {
  power_off(now);
  power_on(now);
}

bool Rs4Device::exchange_unit(std::uint32_t serial_number, TimePoint now) {
  if (serial_number == 0) return false;
  power_off(now);
  scanner::ScannerConfig unit = unit_;
  unit.identity.serial_number = serial_number;
  const bool exchanged = exchange_scanner(unit);
  power_on(now);
  return exchanged;
}

bool Rs4Device::on_bus(TimePoint now) const noexcept {
  (void)now;
  return powered_ && adapter_.station_address().has_value() && !link_down_;
}

void Rs4Device::on_telegram(const dp::fdl::Telegram& t, TimePoint now) {
  if (!on_bus(now)) {
    ++counters_.ignored_while_silent;
    return;
  }
  slave_.on_telegram(t, now);
  after_core_call(now);
}

void Rs4Device::on_time(TimePoint now) {
  if (!powered_) return;
  if (on_bus(now)) {
    slave_.on_time(now);
  } else {
    // The slave is bypassed while the link is down: the adapter (and its scanner) runs on.
    const auto d = adapter_.next_deadline();
    if (d && now >= *d) adapter_.on_time(now);
  }
  after_core_call(now);
}

// Link drop and return around PROFI_CMD_RESET ([RS4 manual §5.2.2]). The reply the slave queued for
// the request that carried the reset still goes out; then the station is silent until the adapter's
// link-down time has passed and comes back as a fresh slave in Wait_Prm.
void Rs4Device::after_core_call(TimePoint now) {
  (void)now;
  const bool wants_down = adapter_.wants_link_down_until().has_value();
  if (wants_down && !link_down_) {
    while (auto t = slave_.take_transmit()) pending_.push_back(std::move(*t));
    link_down_ = true;
    ++counters_.link_drops;
    restart_slave(slave_.address());
  } else if (!wants_down && link_down_) {
    link_down_ = false;
    const auto addr = adapter_.station_address();
    restart_slave(addr ? *addr : slave_.address());
  }
}

std::optional<TimePoint> Rs4Device::next_deadline() const {
  if (!powered_) return std::nullopt;
  if (link_down_) return adapter_.next_deadline();
  return slave_.next_deadline();
}

std::optional<dp::fdl::Telegram> Rs4Device::take_transmit() {
  if (!pending_.empty()) {
    auto t = std::move(pending_.front());
    pending_.pop_front();
    return t;
  }
  if (!powered_ || link_down_) return std::nullopt;
  return slave_.take_transmit();
}

void Rs4Device::on_malformed_frame(std::error_code why) {
  if (powered_ && !link_down_) slave_.on_malformed_frame(why);
}

}  // namespace rs4sim::rs4::device
