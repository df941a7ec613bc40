#include "rs4/device/description.h"

#include "dp/pdu/sap.h"
#include "rs4/scanner/faults.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace rs4sim::rs4::device {
namespace {

using Fault = stream::FaultInfo<Rs4Device>;

// The flags of `rs4sim run --device rs4` (app/devices/device_rs4.cpp).
constexpr std::array kOptions{
    stream::OptionInfo{"--address", 0, dp::pdu::sap::kMaxSlaveAddress,
                       "the hex switches' station address (default 4); repeat it for several "
                       "RS4s on one real-time link",
                       true},
    stream::OptionInfo{"--boot-time", 0, kMaxBootTimeMs,
                       "boot time until operational in ms (default 30000)"},
    stream::OptionInfo{"--command-time", 0, kMaxCommandTimeMs,
                       "how long the RS4 processes a command in ms (default 40; the manual: up "
                       "to 2 minutes)"},
    stream::OptionInfo{"--adapter-response-time", 0, kMaxResponseTimeMs,
                       "the PROFIsafe adapter's response time in ms (default 10, as the "
                       "manual's technical data)"},
    stream::OptionInfo{"--serial-number", 1, 0xFFFFFFFFLL,
                       "the unit's serial number, one per --address in their order (default "
                       "74565); the proxy downloads the archived set to a unit it has not seen "
                       "(device exchange)"},
    stream::OptionInfo{"--state", 1, 0,
                       "the unit's non-volatile memory (parameter set, passwords, serial number, "
                       "address switches) in FILE, one per --address: loaded at start, written "
                       "on every change, so a restart is the same unit with the same set"},
    stream::OptionInfo{"--rs232", 1, 0,
                       "serve the RS232 interface behind the PC adapter: pty | "
                       "serial:DEVICE[@BAUD] (SIGUSR1 attaches the PC adapter, SIGUSR2 removes "
                       "it)"},
    stream::OptionInfo{"--pc-adapter", 1, 0, "the PC adapter at start: attached | detached"},
    stream::OptionInfo{"--gsd", 1, 0, "the RS4 as the user's GSD describes it (one module)"},
    stream::OptionInfo{"--module", 1, 0, "with --gsd: the module by its GSD name"},
};

template <scanner::Fault F>
bool present(const Rs4Device& d) {
  return d.scanner().faults()[static_cast<std::size_t>(F)].present;
}

// The scanner's faults, named as fault_info() names them (rs4/scanner/faults.cpp).
std::array<Fault, scanner::kFaultCount> faults() {
  using F = scanner::Fault;
  using scanner::fault_info;
  return {{
      {fault_info(F::kOssdCrossCircuit).name, present<F::kOssdCrossCircuit>},
      {fault_info(F::kMotorSpeed).name, present<F::kMotorSpeed>},
      {fault_info(F::kInternalHardware).name, present<F::kInternalHardware>},
      {fault_info(F::kDazzled).name, present<F::kDazzled>},
      {fault_info(F::kWindowContaminated).name, present<F::kWindowContaminated>},
      {fault_info(F::kFieldPairSequence).name, present<F::kFieldPairSequence>},
      {fault_info(F::kFieldPairInvalid).name, present<F::kFieldPairInvalid>},
      {fault_info(F::kUnknownCommand).name, present<F::kUnknownCommand>},
  }};
}

// Whether v[i] came before already.
template <typename T>
bool repeated_at(const std::vector<T>& v, std::size_t i) {
  const auto end = v.begin() + static_cast<long>(i);
  return std::find(v.begin(), end, v[i]) != end;
}

// More values of a per-RS4 flag than RS4s.
std::string more_than_addresses(const RunOptions& o, const std::string& flag, std::size_t given,
                                const std::string& what) {
  return flag + " given " + std::to_string(given) + " times for " +
         std::to_string(o.addresses.size()) + " --address (one " + what +
         " per RS4, in the order of --address)";
}

std::string check_addresses(RunOptions& o) {
  if (o.addresses.empty()) o.addresses.push_back(kDefaultAddress);
  for (std::size_t i = 0; i < o.addresses.size(); ++i) {
    const int a = o.addresses[i];
    if (a < 0 || a > dp::pdu::sap::kMaxSlaveAddress) {
      // The switches allow 126 [RS4 manual §4.5], but that is the delivery address, which
      // never reaches data exchange [docs/decisions.md#rs4-address-126].
      return "--address: " + std::to_string(a) + " is outside 0.." +
             std::to_string(dp::pdu::sap::kMaxSlaveAddress) +
             " (a DP slave in operation; 126 is the delivery address)";
    }
    if (repeated_at(o.addresses, i)) {
      return "--address " + std::to_string(a) +
             " given twice (each RS4 is a station of its own on the link)";
    }
  }
  return {};
}

std::string check_serial_numbers(const RunOptions& o) {
  const auto& n = o.serial_numbers;
  if (n.size() > o.addresses.size()) {
    return more_than_addresses(o, "--serial-number", n.size(), "serial number");
  }
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (n[i] < 1 || n[i] > 0xFFFFFFFFLL) {
      return "--serial-number: " + std::to_string(n[i]) +
             " is outside 1..4294967295 (the RS4's identity holds 32 bits; 0 means none)";
    }
    if (repeated_at(n, i)) {
      return "--serial-number " + std::to_string(n[i]) + " given twice (every unit has its own)";
    }
  }
  return {};
}

std::string check_state_files(const RunOptions& o) {
  const auto& f = o.state_files;
  if (f.size() > o.addresses.size())
    return more_than_addresses(o, "--state", f.size(), "state file");
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i].empty()) return "--state: an empty file name";
    if (repeated_at(f, i))
      return "--state " + f[i] + " given twice (every unit has its own memory)";
  }
  return {};
}

std::string check_times(RunOptions& o) {
  if (*o.boot_time_ms < 0 || *o.boot_time_ms > kMaxBootTimeMs) {
    return "--boot-time: " + std::to_string(*o.boot_time_ms) + " ms is outside 0..600000";
  }
  if (!o.command_time_ms) o.command_time_ms = kDefaultCommandTimeMs;
  if (*o.command_time_ms < 0 || *o.command_time_ms > kMaxCommandTimeMs) {
    return "--command-time: " + std::to_string(*o.command_time_ms) +
           " ms is outside 0..120000 (the manual: the RS4 needs up to 2 minutes, "
           "[RS4 manual §5.2.1])";
  }
  if (!o.response_time_ms) o.response_time_ms = kDefaultResponseTimeMs;
  if (*o.response_time_ms < 0 || *o.response_time_ms > kMaxResponseTimeMs) {
    return "--adapter-response-time: " + std::to_string(*o.response_time_ms) +
           " ms is outside 0..1000";
  }
  return {};
}

}  // namespace

// How the API finds its address.
constexpr std::string_view kAddressRule =
    "its station address 0..125 from the hex switches [RS4 manual §4.5]";

const Description& description() {
  static const auto fault_table = faults();
  // kind, --device word, title, link, address rule, counters message, and the tables
  static const Description d(stream::DeviceKind::kRs4, "rs4", "Leuze ROTOSCAN RS4/PROFIsafe",
                             stream::LinkKind::kProfibusDp, kAddressRule, "", kOptions, {},
                             fault_table);
  return d;
}

std::string check_run_options(RunOptions& o) {
  if (o.module && !o.gsd) return "--module needs --gsd FILE (the built-in GSD has one module)";
  if (!o.boot_time_ms) o.boot_time_ms = kDefaultBootTimeMs;
  if (auto why = check_addresses(o); !why.empty()) return why;
  if (auto why = check_serial_numbers(o); !why.empty()) return why;
  if (auto why = check_state_files(o); !why.empty()) return why;
  if (o.rs232 && o.addresses.size() > 1) return "--rs232 serves one RS4; run it with one --address";
  return check_times(o);
}

}  // namespace rs4sim::rs4::device
