#pragma once
// What the curtain counted on its line: frames cut, answered, streamed, dropped per reason
// ([GridScan manual §10.2]: the checks on every frame; [GridScan manual §11]: one request
// per cycle).

#include <cstdint>

namespace rs4sim::gridscan {

struct Counters {
  std::uint64_t frames = 0;      // frames cut by idle gap
  std::uint64_t answered = 0;    // requests answered (incl. communication tests)
  std::uint64_t comm_tests = 0;  // 0x23 processed
  std::uint64_t streamed = 0;    // unsolicited cycle messages (streaming, alignment)
  std::uint64_t truncated = 0;   // fewer than 10 bytes
  std::uint64_t oversized = 0;   // more than 10 bytes (requests carry no payload)
  std::uint64_t bad_sync = 0;
  std::uint64_t bad_crc = 0;
  std::uint64_t bad_seq = 0;
  std::uint64_t unknown_id = 0;
  std::uint64_t direction_bit = 0;  // request with ID bit 7 set
  std::uint64_t busy = 0;           // a second request in the same cycle
  std::uint64_t not_ready = 0;      // before the power-up Reduced state
  std::uint64_t restarts = 0;       // configuration changes
  std::uint64_t mode_fallbacks = 0;  // mode activations that failed into polling (a fault)
  [[nodiscard]] std::uint64_t dropped() const {
    return truncated + oversized + bad_sync + bad_crc + bad_seq + unknown_id + direction_bit +
           busy + not_ready;
  }
};

}  // namespace rs4sim::gridscan
