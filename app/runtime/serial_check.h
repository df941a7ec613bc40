#pragma once
// `rs4sim serial-check` (docs/serial.md): what a serial port and its adapter give a PROFIBUS
// line. The adapter (driver, latency timer, low-latency flag, RS-485 mode; stream/
// serial_adapter.h), the measured turnaround, and the slot time TSL to enter in the
// engineering tool for each baud rate.
//
// The turnaround is measured with FDL_Status requests (SD1, FC 0x49 [IEC 61158-4-3 frame
// control]: every station answers them in any state, [IEC 61158-6-3 FDL_Status]) sent to
// `--address`: against a running rs4sim (or any DP slave) on the other end the reply is an
// SD1 from that address; against a loopback plug (TX wired to RX) the request itself comes
// back. Either way the round trip minus the wire time of the characters is what the line's
// two ends add: the time a reply needs beyond the wire.

#include "dp/time/baud_rate.h"

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::app {

// One row of the slot-time table.
struct SlotTimeRow {
  dp::BaudRate rate;
  std::optional<std::uint32_t> bits;  // nullopt: needs more than 16383 bit times (TSL's limit)
  double ms = 0;                      // the slot time the row asks for
  bool floor = false;                 // a tested setting decided it, not the measurement
  bool tested = false;                // profirust tested a setting at this rate or a slower one
                                      // of its range (up to 500k); faster rates are not advised
};

// The slot time to enter for each rate: twice the measured worst turnaround plus the reply's
// first character, and never below profirust's tested settings (TSL 30 ms up to 45.45 kbit/s,
// tested at 19.2k; 8 ms at 93.75k … 500k). A PC's turnaround does not shrink with the rate, so
// the faster rates, where nothing was tested, keep the 8 ms floor too: from 93.75k on a faster
// rate asks for less only by its shorter first character. Bit times rounded up; above 16383
// bit times [IEC 61158-4-3 bus parameters, timing] the rate cannot be used with this line.
[[nodiscard]] std::vector<SlotTimeRow> slot_time_table(std::chrono::nanoseconds worst_turnaround);
// The rate to use: the fastest tested one (up to 500k) this line can serve; nullopt when none
// can [docs/decisions.md#serial-check-rate].
[[nodiscard]] std::optional<SlotTimeRow> recommended_rate(const std::vector<SlotTimeRow>& rows);
void print_slot_time_table(std::ostream& out, const std::vector<SlotTimeRow>& rows);

// What to check when nothing answered: on a pseudo-terminal the other end (no wire, no
// termination), on a real port the wiring.
[[nodiscard]] std::string nothing_answered_advice(bool pty, const std::string& port,
                                                  const std::string& baud, int address);

struct SerialCheckOptions {
  std::string port;
  std::string baud = "187.5k";
  int address = 4;       // the station asked (rs4sim run's default RS4 address)
  int master = 1;        // our source address
  int count = 50;        // requests
  int timeout_ms = 200;  // per request
  std::string sysfs = "/sys";
};

// Runs the check, prints the report on `out`; returns the exit code (1: the port cannot be
// opened or nothing answered).
int serial_check(const SerialCheckOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs4sim::app
