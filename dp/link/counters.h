#pragma once
// Per-station counters kept by every link (memory bus, serial/pty, UDP). A link never
// throws on bad wire input: it drops the bytes and counts them here.

#include <cstdint>

namespace rs4sim::dp::link {

struct StationCounters {
  std::uint64_t sent = 0;         // telegrams the station handed to the link
  std::uint64_t received = 0;     // well-formed telegrams delivered to the station
  std::uint64_t malformed = 0;    // frames its decoder rejected (bad FCS, length, …)
  std::uint64_t dropped = 0;      // its telegrams lost by fault injection
  std::uint64_t corrupted = 0;    // its telegrams corrupted by fault injection
  std::uint64_t delayed = 0;      // its telegrams delayed by fault injection
  std::uint64_t silenced = 0;     // telegrams not sent/received because it was silenced
  std::uint64_t unroutable = 0;   // its replies with no request to answer (SC/response)
  std::uint64_t send_errors = 0;  // OS-level send/receive failures (serial/UDP)
  std::uint64_t foreign = 0;      // UDP datagrams from a host other than the peer

  friend bool operator==(const StationCounters&, const StationCounters&) = default;
};

}  // namespace rs4sim::dp::link
