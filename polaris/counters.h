#pragma once
// What the barrier counted on its Modbus RTU line.

#include <cstdint>

namespace rs4sim::polaris {

// Every received frame lands in exactly one of the first thirteen counters.
struct Counters {
  std::uint64_t requests = 0;  // well-formed reads for us (data or configuration block)
  std::uint64_t crc_errors = 0;
  std::uint64_t too_short = 0;        // < 4 bytes
  std::uint64_t oversized = 0;        // > 256 bytes
  std::uint64_t broadcasts = 0;       // address 0 (writes too): not supported, ignored
  std::uint64_t foreign_address = 0;  // for another slave, ignored
  std::uint64_t bad_function = 0;     // not FC 3/4/6/16, or FC 6/16 outside the config block
  std::uint64_t bad_request = 0;      // wrong length or 485MB word count -> exception 0x03
  std::uint64_t bad_start = 0;        // outside the data block -> exception 0x02
  // EXTENSION (docs/polaris.md "Configuration registers"):
  std::uint64_t busy = 0;            // data reads during auto-calibration -> exception 0x06
  std::uint64_t writes = 0;          // FC 6/16 to the configuration block applied
  std::uint64_t refused_writes = 0;  // FC 6/16 refused: exception 02/03/04/06
  std::uint64_t answers_ignored = 0;  // master role: the slave's replies
  std::uint64_t exceptions_sent = 0;
  std::uint64_t frames_sent = 0;  // answers and pushes put on the line
  std::uint64_t suppressed = 0;   // frames the silent fault swallowed
};

}  // namespace rs4sim::polaris
