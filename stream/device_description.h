#pragma once
// One description of a device, written once in its own library (gridscan/description.h,
// metron/description.h, polaris/description.h, rs4/device/description.h,
// dp/devices/description.h): its kind, the protocol on its link, its address rule, the
// options of `rs4sim run` it takes (name, range, help), and its counters and faults as
// tables of (name, accessor). The edges read it instead of typing the facts again: the CLI's
// option checks (app/devices/device_options.h), the API's counters and faults_present
// (rpc/line_service_support.h fills the .proto message by the field names), the end-of-run
// summary, the run's station list (rs4sim.v1.Run/Describe) and the live page.
// The shape follows open62541's type descriptions (one table per type that every printer
// and encoder reads) and p-net's pnet_api.h (one public description the stack reads).
// Header-only and free of any device: the lowest layer every device library sits on.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::stream {

// What a station is; the API's rs4sim.v1.StationKind has one value per kind (run.proto).
enum class DeviceKind : std::uint8_t {
  kRs4 = 1,       // the RS4/PROFIsafe (rs4/)
  kGeneric = 2,   // a generic DP slave, by ident/Cfg or its GSD (dp/devices/)
  kEcho = 3,      // the byte echo (stream/echo_device.h), no API of its own
  kGridScan = 4,  // CEDES GridScan/Pro SI, RC (gridscan/)
  kMetron = 5,    // ReeR METRON (metron/)
  kPolaris = 6,   // Optoscan Polaris (polaris/)
};

// The protocol on the device's link. A byte line's kind is also what its capture names in each
// record (app/runtime/line_capture.h, stream::LineProtocol), so that the dissector
// (tools/wireshark/rs4sim.lua) needs no guessing: the values are the capture format's, never
// renumber them. A device with a protocol of its own adds its value here, and nowhere else.
enum class LinkKind : std::uint8_t {
  kRaw = 0,        // bytes without a protocol (the echo device)
  kGridScan = 1,   // CEDES frames on RS-485 [GridScan manual §9.2]
  kMetron = 2,     // METRON slave/standard line [METRON manual "Serial line management"]
  kModbusRtu = 3,  // Modbus RTU ADUs (the Polaris) [Modbus over Serial Line V1.02 §2.5.1]
  kRs4Rs232 = 4,   // the RS4's RS232 interface [RS4 manual §5.2.3]
  // PROFIBUS DP stations on a bus [IEC 61158-6-3]: no byte line, never in a line's capture
  // (a bus's capture is dp/link/pcap.h's own).
  kProfibusDp = 255,
};

// One option of `rs4sim run` the device takes. A numeric option's range is min..max;
// min > max: not a number (a word or a file).
struct OptionInfo {
  std::string_view flag;  // "--beams"
  long long min = 1;
  long long max = 0;
  std::string_view help;  // what it sets on this device
  bool repeats = false;   // given more than once (the RS4's --address: one RS4 each)
};

// One counter: the .proto field's name in the device's Counters message, the words of the
// end-of-run summary, and the value (index 0..size-1; size > 1: a repeated field, E1..E5).
template <typename Counters>
struct CounterInfo {
  std::string_view name;
  std::string_view label;
  std::uint64_t (*value)(const Counters&, std::size_t index);
  std::size_t size = 1;
};

// A counter that is a member of Counters.
template <auto Member, typename Counters>
std::uint64_t member_value(const Counters& c, std::size_t) {
  return c.*Member;
}
// One element of an array member of Counters.
template <auto Member, typename Counters>
std::uint64_t element_value(const Counters& c, std::size_t index) {
  return (c.*Member)[index];
}

// One fault the API injects: its word in faults_present ("bad-checksum"; the API's enum
// value is the word in capitals with the device's prefix, METRON_FAULT_BAD_CHECKSUM) and
// whether it is on now.
template <typename Device>
struct FaultInfo {
  std::string_view name;
  bool (*present)(const Device&);
};

// The counters of a device whose API has no counters message (the RS4, a generic slave).
struct NoCounters {};

// The whole description. `Device` is the device's core class (its counters() and what the
// faults read), `Counters` what counters() returns.
template <typename Device, typename Counters>
struct DeviceDescription {
  constexpr DeviceDescription(DeviceKind k, std::string_view n, std::string_view t, LinkKind l,
                              std::string_view rule, std::string_view message,
                              std::span<const OptionInfo> o,
                              std::span<const CounterInfo<Counters>> c,
                              std::span<const FaultInfo<Device>> f)
      : kind(k),
        name(n),
        title(t),
        link(l),
        address_rule(rule),
        counters_message(message),
        options(o),
        counters(c),
        faults(f) {}

  DeviceKind kind;
  std::string_view name;   // the --device word, "metron"
  std::string_view title;  // "ReeR METRON measuring light curtain"
  LinkKind link;
  std::string_view address_rule;      // how its address in the API is found
  std::string_view counters_message;  // the .proto message of its counters, "MetronCounters"
  std::span<const OptionInfo> options;
  std::span<const CounterInfo<Counters>> counters;
  std::span<const FaultInfo<Device>> faults;
};

// The words of the faults that are on now, in the description's order.
template <typename Device, typename Counters>
std::vector<std::string> faults_present(const DeviceDescription<Device, Counters>& d,
                                        const Device& device) {
  std::vector<std::string> out;
  for (const auto& f : d.faults) {
    if (f.present(device)) out.emplace_back(f.name);
  }
  return out;
}

// "messages 3, executed 2, ..., E1..E5 0/1/0/0/0": every counter of the description, in its
// order, with its summary words.
template <typename Device, typename Counters>
std::string counters_summary(const stream::DeviceDescription<Device, Counters>& d,
                             const Counters& k) {
  std::string out;
  for (const auto& c : d.counters) {
    out += (out.empty() ? "" : ", ") + std::string(c.label) + " ";
    for (std::size_t i = 0; i < c.size; ++i) {
      out += (i == 0 ? "" : "/") + std::to_string(c.value(k, i));
    }
  }
  return out;
}

// The --device word of a kind ("rs4", "generic", ...).
constexpr std::string_view to_string(DeviceKind k) {
  switch (k) {
    case DeviceKind::kRs4: return "rs4";
    case DeviceKind::kGeneric: return "generic";
    case DeviceKind::kEcho: return "echo";
    case DeviceKind::kGridScan: return "gridscan";
    case DeviceKind::kMetron: return "metron";
    case DeviceKind::kPolaris: return "polaris";
  }
  return "?";
}

}  // namespace rs4sim::stream
