#include "gridscan/description.h"

#include <array>
#include <string_view>

namespace rs4sim::gridscan {
namespace {

using stream::member_value;
using C = Counters;
using Counter = stream::CounterInfo<Counters>;
using Fault = stream::FaultInfo<Device>;

// The flags of `rs4sim run --device gridscan` (app/devices/device_gridscan.cpp fills Options).
constexpr std::array kOptions{
    stream::OptionInfo{"--elements", 12, 60, "elements per edge [GridScan manual §11]"},
    stream::OptionInfo{"--mode", 1, 0, "blanking | static[,cycle=<ms>] (gridscan/mode_spec.h)"},
    stream::OptionInfo{"--door", 0, 60, "door position at start: elements below the door"},
    stream::OptionInfo{"--blocked", 1, 60, "interrupted elements at start, e.g. 3-5"},
    stream::OptionInfo{"--mains", 1, 0, "on | off: the mains at start"},
};

std::uint64_t dropped(const Counters& c, std::size_t) { return c.dropped(); }

// The checks on every frame [GridScan manual §10.2], one request per cycle
// [GridScan manual §11]; dropped is the sum of the reasons after it.
constexpr std::array kCounters{
    Counter{"frames", "frames", member_value<&C::frames>},
    Counter{"answered", "answered", member_value<&C::answered>},
    Counter{"comm_tests", "communication tests", member_value<&C::comm_tests>},
    Counter{"streamed", "streamed", member_value<&C::streamed>},
    Counter{"dropped", "dropped", dropped},
    Counter{"truncated", "truncated", member_value<&C::truncated>},
    Counter{"oversized", "oversized", member_value<&C::oversized>},
    Counter{"bad_sync", "sync", member_value<&C::bad_sync>},
    Counter{"bad_crc", "CRC", member_value<&C::bad_crc>},
    Counter{"bad_seq", "SeqCnt", member_value<&C::bad_seq>},
    Counter{"unknown_id", "ID", member_value<&C::unknown_id>},
    Counter{"direction_bit", "direction", member_value<&C::direction_bit>},
    Counter{"busy", "busy", member_value<&C::busy>},
    Counter{"not_ready", "not ready", member_value<&C::not_ready>},
    Counter{"restarts", "restarts", member_value<&C::restarts>},
    Counter{"mode_fallbacks", "mode fallbacks", member_value<&C::mode_fallbacks>},
};

// [GridScan manual §10.2], in the order of GridScanFault.
constexpr std::array kFaults{
    Fault{"late", [](const Device& d) { return d.faults().transmit.late.count() > 0; }},
    Fault{"wrong-seq", [](const Device& d) { return d.faults().wrong_seq; }},
    Fault{"direction-bit", [](const Device& d) { return d.faults().direction_bit; }},
    Fault{"bad-crc", [](const Device& d) { return d.faults().bad_crc; }},
    Fault{"internal-failure", [](const Device& d) { return d.scene().internal_failure; }},
    Fault{"silent", [](const Device& d) { return d.faults().transmit.silent; }},
    Fault{"config-not-set", [](const Device& d) { return d.faults().config_not_set; }},
    Fault{"repeat-frames", [](const Device& d) { return d.faults().repeat_frames; }},
    Fault{"insert-frames", [](const Device& d) { return d.faults().insert_frames; }},
    Fault{"test-ignored", [](const Device& d) { return d.faults().test_ignored; }},
    Fault{"stuck-free", [](const Device& d) { return d.faults().stuck_free != 0; }},
    Fault{"mode-activation-fails",
          [](const Device& d) { return d.faults().mode_activation_fails; }},
};

}  // namespace

// How the API finds its address.
constexpr std::string_view kAddressRule =
    "0: the RS485 interface is point-to-point and carries no address "
    "[GridScan manual §9]";

const Description& description() {
  // kind, --device word, title, link, address rule, counters message, and the tables
  static const Description d(stream::DeviceKind::kGridScan, "gridscan", "CEDES GridScan/Pro SI, RC",
                             stream::LinkKind::kGridScan, kAddressRule, "GridScanCounters",
                             kOptions, kCounters, kFaults);
  return d;
}

}  // namespace rs4sim::gridscan
