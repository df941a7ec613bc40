#pragma once
// Faults a controller talking to a METRON must catch, injected on the Receiver's output
// (the project's controls, [docs/metron.md#faults]). They stay on until cleared.

#include "stream/clock.h"

#include <cstdint>

namespace rs4sim::metron {

struct Faults {
  bool silent = false;             // no reply / no report goes out
  stream::Duration extra_delay{};  // every frame goes out this much later (late answer)
  bool bad_checksum = false;       // the checksum byte is inverted
  bool wrong_node = false;         // node mode: the reply carries node + 1
  bool truncate = false;           // the last byte of every frame is missing

  friend bool operator==(const Faults&, const Faults&) = default;
};

struct Counters {
  // slave line mode
  std::uint64_t messages = 0;  // delimited messages, good or bad
  std::uint64_t executed = 0;
  std::uint64_t frames_sent = 0;  // replies and reports that went out
  std::uint64_t errors[5] = {};   // answers (or broadcast drops) per E1..E5
  std::uint64_t parity_rejected = 0;
  std::uint64_t not_for_us = 0;
  std::uint64_t broadcast_ignored = 0;
  std::uint64_t noise_bytes = 0;
  std::uint64_t truncated = 0;
  std::uint64_t too_long = 0;
  std::uint64_t resync_bytes = 0;
  std::uint64_t ignored_in_reset = 0;  // bytes that arrived while the Receiver restarted
  std::uint64_t resets = 0;
  // standard line mode
  std::uint64_t reports = 0;
  std::uint64_t reports_dropped = 0;
  std::uint64_t report_requests = 0;
  std::uint64_t other_bytes = 0;
  // fault injection
  std::uint64_t suppressed = 0;  // frames the `silent` fault swallowed
};

}  // namespace rs4sim::metron
