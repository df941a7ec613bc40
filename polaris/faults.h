#pragma once
// Faults a controller must catch on the barrier's line; late and silent are the shared
// transmit faults, the CRC fault is Modbus RTU's own.

#include "stream/transmit_fault.h"

namespace rs4sim::polaris {

// Faults the controller must catch, applied to every frame sent while set.
struct Faults {
  bool bad_crc = false;              // the CRC's high byte inverted
  stream::TransmitFault transmit{};  // silent: nothing sent (slave: no answer; master: no push)
  friend bool operator==(const Faults&, const Faults&) = default;
};

}  // namespace rs4sim::polaris
