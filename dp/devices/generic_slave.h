#pragma once
// One generic virtual slave as a single dp::Station: the dp::slave::Slave protocol core with a
// GenericDevice behind it (see generic_device.h for the device's behaviour).

#include "dp/devices/generic_device.h"
#include "dp/slave/slave.h"

namespace rs4sim::dp::devices {

struct GenericSlaveConfig {
  std::uint8_t address = 126;
  std::uint16_t ident_number = 0;
  std::vector<std::uint8_t> cfg;  // real configuration identifiers
  bool dpv1 = true;
};

class GenericSlave final : public Station {
 public:
  // Throws std::system_error on a bad configuration (address, identifiers).
  explicit GenericSlave(const GenericSlaveConfig& config);
  GenericSlave(const GenericSlave&) = delete;
  GenericSlave& operator=(const GenericSlave&) = delete;

  [[nodiscard]] std::uint8_t address() const override { return slave_.address(); }
  void on_telegram(const fdl::Telegram& t, TimePoint now) override { slave_.on_telegram(t, now); }
  void on_time(TimePoint now) override { slave_.on_time(now); }
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override {
    return slave_.next_deadline();
  }
  std::optional<fdl::Telegram> take_transmit() override { return slave_.take_transmit(); }
  const fdl::Telegram* next_transmit(fdl::Telegram& scratch) override {
    return slave_.next_transmit(scratch);
  }
  void on_malformed_frame(std::error_code why) override { slave_.on_malformed_frame(why); }
  [[nodiscard]] std::uint16_t min_tsdr_bits() const override { return slave_.min_tsdr_bits(); }

  [[nodiscard]] GenericDevice& device() { return device_; }
  [[nodiscard]] const GenericDevice& device() const { return device_; }
  [[nodiscard]] dp::slave::Slave& slave() { return slave_; }
  [[nodiscard]] const dp::slave::Slave& slave() const { return slave_; }

 private:
  static dp::slave::Config slave_config(const GenericSlaveConfig& c);

  // Before slave_: the dp::slave::Slave constructor calls device_.on_attach().
  GenericDevice device_;
  dp::slave::Slave slave_;
};

}  // namespace rs4sim::dp::devices
