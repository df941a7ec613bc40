#pragma once
// Faults a controller talking to a METRON must catch, injected on the Receiver's output
// (the project's controls, [docs/metron.md#faults]). They stay on until cleared.

#include "stream/transmit_fault.h"

namespace rs4sim::metron {

struct Faults {
  stream::TransmitFault transmit{};  // silent: no reply / no report goes out; late answer
  bool bad_checksum = false;         // the checksum byte is inverted
  bool wrong_node = false;           // node mode: the reply carries node + 1
  bool truncate = false;             // the last byte of every frame is missing

  friend bool operator==(const Faults&, const Faults&) = default;
};

}  // namespace rs4sim::metron
