#include "dp/devices/generic_slave.h"

namespace rs4sim::dp::devices {

dp::slave::Config GenericSlave::slave_config(const GenericSlaveConfig& c) {
  dp::slave::Config s;
  s.address = c.address;
  s.ident_number = c.ident_number;
  s.dpv1 = c.dpv1;
  return s;
}

GenericSlave::GenericSlave(const GenericSlaveConfig& config)
    : device_(GenericDeviceConfig{config.cfg}), slave_(slave_config(config), device_) {
  slave_.set_wake_handler([this] { wake(); });  // the slave's wake-ups are this station's
}

}  // namespace rs4sim::dp::devices
