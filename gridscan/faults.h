#pragma once
// Fault injection for each check a door controller must make on every response to keep
// SIL 2 ([GridScan manual §10.2]): timing (10.2.1), sequence counter, direction bit and
// CRC (10.2.2), internal fault (10.2.3; bit 9, in the Scene). The faults act on the
// frames as they go on the wire; the curtain's own counters stay right, so clearing a
// fault brings back correct frames at once.

#include "stream/transmit_fault.h"

namespace rs4sim::gridscan {

struct FaultControls {
  // late: every frame of a cycle leaves this much after its end; silent: nothing is sent
  // (communication loss)
  stream::TransmitFault transmit{};
  bool wrong_seq = false;       // SeqCnt one higher than it should be
  bool direction_bit = false;   // ID bit 7 cleared (the CRC is computed over the wrong ID)
  bool bad_crc = false;         // bit 0 of the CRC's first byte inverted
  bool config_not_set = false;  // Config: Set static/blanking fail with code 1 "not set"

  friend bool operator==(const FaultControls&, const FaultControls&) = default;
};

}  // namespace rs4sim::gridscan
