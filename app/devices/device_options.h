#pragma once
// The device options of `rs4sim run` (app/devices/device_registry.h DeviceOptions) beyond parsing:
// which flag is which, refusing the ones a device entry does not use, and the parsers of
// the byte devices' values (--blocked ranges, --baud as a plain bit rate, --format).
// Errors are UsageError with the reason (exit 2).

#include "app/devices/device_registry.h"
#include "stream/byte_counters.h"
#include "stream/device_description.h"
#include "stream/line_settings.h"

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string_view>
#include <ostream>
#include <string>
#include <vector>

namespace rs4sim::app {

enum class DeviceFlag : std::uint8_t {
  kAddress,
  kAddresses,  // --address given more than once (DeviceOptions::more_addresses)
  kIdent,
  kCfg,
  kBootTime,
  kCommandTime,
  kResponseTime,
  kBaud,
  kFormat,
  kElements,
  kBeams,
  kModel,
  kMode,
  kBlocked,
  kDoor,
  kNode,
  kRs232,
  kPcAdapter,
  kSerialNumber,
  kState,
  kGsd,     // --gsd FILE (generic)
  kModule,  // --module NAME, repeatable (with --gsd)
  kFDestAdd,  // --f-dest-add N (with --gsd: the F-modules' F_Dest_Add)
  kWireTable,  // --wire-table FILE (METRON)
  kMains,      // --mains on | off (GridScan)
};

// "--elements".
[[nodiscard]] const char* flag_name(DeviceFlag f);

// Throws UsageError for the first option given that `device` does not use:
// "--door is not an option of --device polaris"; a repeated --address that `device` does not
// take (kAddresses): "--address given 2 times: --device generic is one station ...".
void refuse_unused(const DeviceOptions& o, const std::string& device,
                   std::initializer_list<DeviceFlag> used);
// The same for the options a device's description lists (stream/device_description.h): a
// flag is used when its name is there; the repeated --address when "--address" repeats.
void refuse_unused(const DeviceOptions& o, std::string_view device,
                   std::span<const stream::OptionInfo> used);

// The help of a flag of `rs4sim run`: what it sets on each registered device that takes
// it, from their descriptions ("gridscan: elements per edge ...; metron: ...").
[[nodiscard]] std::string option_help(std::string_view flag);

// "9-13,25-34" → 9..13, 25..34: sorted, each number once (overlapping ranges merge);
// numbers are 1-based. Throws UsageError naming the bad item.
[[nodiscard]] std::vector<int> parse_blocked(const std::string& text);

// Throws UsageError when a --blocked number is above `count` ("elements", "beams").
void check_blocked(const DeviceOptions& o, int count, const std::string& what);

// "19200" → 19200 bit/s (a plain number, 50 … 12000000). Throws UsageError.
[[nodiscard]] std::uint32_t parse_bit_rate(const std::string& text);

// The line format a byte device runs with: `defaults` with --baud and --format applied.
// Throws UsageError for a malformed --format. The entry checks what its device allows.
[[nodiscard]] stream::LineSettings line_settings(const DeviceOptions& o,
                                                 stream::LineSettings defaults);

// The end-of-run line of a byte device: "metron: <counters_summary><extra>, bytes received N,
// sent N, link errors N".
template <typename Device, typename Counters>
void print_line_summary(std::ostream& out, const stream::DeviceDescription<Device, Counters>& d,
                        const Counters& k, const std::string& extra,
                        const stream::ByteCounters& c) {
  out << d.name << ": " << stream::counters_summary(d, k) << extra << ", bytes received "
      << c.bytes_received << ", sent " << c.bytes_sent << ", link errors " << c.link_errors
      << std::endl;
}

}  // namespace rs4sim::app
