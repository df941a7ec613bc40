#pragma once
// What the METRON counted, in slave line mode and in standard line mode.

#include <cstdint>

namespace rs4sim::metron {

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
