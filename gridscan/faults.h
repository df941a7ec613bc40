#pragma once
// Fault injection for each check a door controller must make on every response to keep
// SIL 2 ([GridScan manual §10.2]): timing (10.2.1), sequence counter, direction bit and
// CRC (10.2.2), internal fault (10.2.3; bit 9, in the Scene). The transmission faults act
// on the frames as they go on the wire; the curtain's own counters stay right, so clearing
// a fault brings back correct frames at once. The sequence counter check is "Detection of
// data repetition, incorrect sequence, loss or insertion" ([GridScan manual §10.2.2]): one
// fault for each. The curtain's own failures a controller must catch: a Test input (0x40)
// that does not test ([GridScan manual §10.1.2]: Cat. 2, the controller's periodic test),
// elements stuck free, and a mode activation that fails, after which "the light curtain
// switches automatically to the polling mode" ([GridScan manual §10.1.1]).

#include "stream/transmit_fault.h"

#include <cstdint>

namespace rs4sim::gridscan {

struct Faults {
  // late: every frame of a cycle leaves this much after its end; silent: nothing is sent
  // (communication loss)
  stream::TransmitFault transmit{};
  bool wrong_seq = false;       // SeqCnt one higher than it should be (a lost message)
  // Repetition: every frame goes twice, byte for byte (the second with the same SeqCnt).
  bool repeat_frames = false;
  // Insertion: before every frame, the previous frame sent (its ID and payload, stale)
  // sealed with this frame's SeqCnt and a valid CRC; the real frame follows with the same
  // SeqCnt (DECISION: what an inserted frame carries, docs/gridscan.md#faults).
  bool insert_frames = false;
  bool direction_bit = false;   // ID bit 7 cleared (the CRC is computed over the wrong ID)
  bool bad_crc = false;         // bit 0 of the CRC's first byte inverted
  bool config_not_set = false;  // Config: Set static/blanking fail with code 1 "not set"
  // Test input (0x40) answered, but the next state message shows the real state instead of
  // every element interrupted: the controller's test must fail.
  bool test_ignored = false;
  // Elements (bit e-1 = element e) that read free whatever is in front of them, also in a
  // test; a dangerous failure only the test shows (Full state, per element).
  std::uint64_t stuck_free = 0;
  // Mode: Set full/reduced streaming or stand-by is answered, and the curtain stays in (or
  // falls back to) polling mode.
  bool mode_activation_fails = false;

  friend bool operator==(const Faults&, const Faults&) = default;
};

}  // namespace rs4sim::gridscan
