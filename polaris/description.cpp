#include "polaris/description.h"

#include "modbus/rtu_frame.h"

#include <array>
#include <string_view>

namespace rs4sim::polaris {
namespace {

using stream::member_value;
using C = Counters;
using Counter = stream::CounterInfo<Counters>;
using Fault = stream::FaultInfo<Device>;

// The flags of `rs4sim run --device polaris` (app/devices/device_polaris.cpp fills Options).
constexpr std::array kOptions{
    stream::OptionInfo{"--address", modbus::kMinSlaveAddress, modbus::kMaxSlaveAddress,
                       "Modbus address [Modbus serial line V1.02 §2.2]"},
    stream::OptionInfo{"--baud", 19200, 115200, "bit rate [Polaris manual §8.1]"},
    stream::OptionInfo{"--beams", 1, 0xFFFF, "beam count (the family makes some)"},
    stream::OptionInfo{"--model", 1, 0, "PLi02 | PLi05 | PLi12 | PL10 | PL24 | PL48"},
    stream::OptionInfo{"--mode", 1, 0, "485MB | FL1 | FL4 | FL10[,settings] (polaris/mode_spec.h)"},
    stream::OptionInfo{"--blocked", 1, 0xFFFF, "interrupted beams at start, e.g. 9-13,25-34"},
};

// Every received frame lands in one of the first thirteen (polaris/counters.h).
constexpr std::array kCounters{
    Counter{"requests", "requests", member_value<&C::requests>},
    Counter{"crc_errors", "CRC errors", member_value<&C::crc_errors>},
    Counter{"too_short", "too short", member_value<&C::too_short>},
    Counter{"oversized", "oversized", member_value<&C::oversized>},
    Counter{"broadcasts", "broadcasts", member_value<&C::broadcasts>},
    Counter{"foreign_address", "other addresses", member_value<&C::foreign_address>},
    Counter{"bad_function", "bad function", member_value<&C::bad_function>},
    Counter{"bad_request", "bad request", member_value<&C::bad_request>},
    Counter{"bad_start", "bad start", member_value<&C::bad_start>},
    Counter{"busy", "busy", member_value<&C::busy>},
    Counter{"writes", "configuration writes", member_value<&C::writes>},
    Counter{"refused_writes", "refused writes", member_value<&C::refused_writes>},
    Counter{"answers_ignored", "answers ignored", member_value<&C::answers_ignored>},
    Counter{"exceptions_sent", "exceptions sent", member_value<&C::exceptions_sent>},
    Counter{"frames_sent", "frames sent", member_value<&C::frames_sent>},
    Counter{"suppressed", "suppressed", member_value<&C::suppressed>},
};

// In the order of PolarisFault.
constexpr std::array kFaults{
    Fault{"bad-crc", [](const Device& d) { return d.faults().bad_crc; }},
    Fault{"silent", [](const Device& d) { return d.faults().transmit.silent; }},
    Fault{"late", [](const Device& d) { return d.faults().transmit.late.count() > 0; }},
};

}  // namespace

// How the API finds its address.
constexpr std::string_view kAddressRule =
    "its Modbus address, 1..247 (--address) [Modbus serial line V1.02 §2.2]";

const Description& description() {
  // kind, --device word, title, link, address rule, counters message, and the tables
  static const Description d(stream::DeviceKind::kPolaris, "polaris",
                             "Optoscan Polaris measuring barrier", stream::LinkKind::kModbusRtu,
                             kAddressRule, "PolarisCounters", kOptions, kCounters, kFaults);
  return d;
}

}  // namespace rs4sim::polaris
