#include "metron/description.h"

#include <array>
#include <string_view>

namespace rs4sim::metron {
namespace {

using stream::element_value;
using stream::member_value;
using C = Counters;
using Counter = stream::CounterInfo<Counters>;
using Fault = stream::FaultInfo<Device>;

// The flags of `rs4sim run --device metron` (app/devices/device_metron.cpp fills Options).
constexpr std::array kOptions{
    stream::OptionInfo{"--baud", 50, 12000000, "standard line mode: the bit rate"},
    stream::OptionInfo{"--format", 1, 0, "standard line mode: the parity, e.g. 8E1"},
    stream::OptionInfo{"--beams", 1, kMaxBeams, "beam count (default 24)"},
    stream::OptionInfo{"--mode", 1, 0, "line and reporting mode (metron/mode_spec.h)"},
    stream::OptionInfo{"--blocked", 1, kMaxBeams, "interrupted beams at start, e.g. 9-13"},
    stream::OptionInfo{"--node", 0, kMaxNode, "node mode on, with this node number"},
    stream::OptionInfo{"--wire-table", 1, 0, "byte values and layouts from a JSON file"},
};

// The messages of slave line mode [METRON manual "Slave line mode"], the reports of standard
// line mode [METRON manual "Standard line mode"], and the fault injection's swallowed frames.
constexpr std::array kCounters{
    Counter{"messages", "messages", member_value<&C::messages>},
    Counter{"executed", "executed", member_value<&C::executed>},
    Counter{"frames_sent", "frames sent", member_value<&C::frames_sent>},
    Counter{"errors", "E1..E5", element_value<&C::errors>, 5},
    Counter{"parity_rejected", "parity rejected", member_value<&C::parity_rejected>},
    Counter{"not_for_us", "not for us", member_value<&C::not_for_us>},
    Counter{"broadcast_ignored", "broadcasts ignored", member_value<&C::broadcast_ignored>},
    Counter{"noise_bytes", "noise bytes", member_value<&C::noise_bytes>},
    Counter{"truncated", "truncated", member_value<&C::truncated>},
    Counter{"too_long", "too long", member_value<&C::too_long>},
    Counter{"resync_bytes", "resync bytes", member_value<&C::resync_bytes>},
    Counter{"ignored_in_reset", "ignored in reset", member_value<&C::ignored_in_reset>},
    Counter{"resets", "resets", member_value<&C::resets>},
    Counter{"reports", "reports", member_value<&C::reports>},
    Counter{"reports_dropped", "reports dropped", member_value<&C::reports_dropped>},
    Counter{"report_requests", "report requests", member_value<&C::report_requests>},
    Counter{"other_bytes", "other bytes", member_value<&C::other_bytes>},
    Counter{"suppressed", "suppressed", member_value<&C::suppressed>},
};

// [docs/metron.md#faults], in the order of MetronFault.
constexpr std::array kFaults{
    Fault{"silent", [](const Device& d) { return d.faults().transmit.silent; }},
    Fault{"late", [](const Device& d) { return d.faults().transmit.late.count() > 0; }},
    Fault{"bad-checksum", [](const Device& d) { return d.faults().bad_checksum; }},
    Fault{"wrong-node", [](const Device& d) { return d.faults().wrong_node; }},
    Fault{"truncate", [](const Device& d) { return d.faults().truncate; }},
};

}  // namespace

// How the API finds its address.
constexpr std::string_view kAddressRule =
    "the node number with node mode on (0..254), else 0; 255 is the "
    "broadcast address [METRON manual \"With node\"]";

const Description& description() {
  // kind, --device word, title, link, address rule, counters message, and the tables
  static const Description d(stream::DeviceKind::kMetron, "metron",
                             "ReeR METRON measuring light curtain", stream::LinkKind::kMetron,
                             kAddressRule, "MetronCounters", kOptions, kCounters, kFaults);
  return d;
}

}  // namespace rs4sim::metron
