#include "app/devices/device_options.h"

#include "app/runtime/usage_error.h"

#include <algorithm>
#include <charconv>

namespace rs4sim::app {

namespace {

constexpr int kMaxBlocked = 100000;  // far above any device's element or beam count
constexpr std::uint32_t kMinBitRate = 50;
constexpr std::uint32_t kMaxBitRate = 12000000;

bool given(const DeviceOptions& o, DeviceFlag f) {
  switch (f) {
    case DeviceFlag::kAddress: return o.address.has_value();
    case DeviceFlag::kAddresses: return !o.more_addresses.empty();
    case DeviceFlag::kIdent: return !o.ident.empty();
    case DeviceFlag::kCfg: return !o.cfg.empty();
    case DeviceFlag::kBootTime: return o.boot_time_ms.has_value();
    case DeviceFlag::kCommandTime: return o.command_time_ms.has_value();
    case DeviceFlag::kResponseTime: return o.response_time_ms.has_value();
    case DeviceFlag::kBaud: return o.baud.has_value();
    case DeviceFlag::kFormat: return !o.format.empty();
    case DeviceFlag::kElements: return o.elements.has_value();
    case DeviceFlag::kBeams: return o.beams.has_value();
    case DeviceFlag::kModel: return !o.model.empty();
    case DeviceFlag::kMode: return !o.mode.empty();
    case DeviceFlag::kBlocked: return o.blocked.has_value();
    case DeviceFlag::kDoor: return o.door.has_value();
    case DeviceFlag::kNode: return o.node.has_value();
    case DeviceFlag::kRs232: return !o.rs232.empty();
    case DeviceFlag::kPcAdapter: return !o.pc_adapter.empty();
    case DeviceFlag::kSerialNumber: return !o.serial_numbers.empty();
    case DeviceFlag::kState: return !o.state_files.empty();
    case DeviceFlag::kGsd: return !o.gsd.empty();
    case DeviceFlag::kModule: return !o.modules.empty();
    case DeviceFlag::kFDestAdd: return o.f_dest_add.has_value();
    case DeviceFlag::kWireTable: return !o.wire_table.empty();
    case DeviceFlag::kMains: return !o.mains.empty();
  }
  return false;
}

constexpr DeviceFlag kAllFlags[] = {
    DeviceFlag::kAddress,     DeviceFlag::kIdent,        DeviceFlag::kCfg,
    DeviceFlag::kBootTime,    DeviceFlag::kBaud,         DeviceFlag::kFormat,
    DeviceFlag::kElements,    DeviceFlag::kBeams,        DeviceFlag::kModel,
    DeviceFlag::kMode,        DeviceFlag::kBlocked,      DeviceFlag::kDoor,
    DeviceFlag::kNode,        DeviceFlag::kRs232,        DeviceFlag::kPcAdapter,
    DeviceFlag::kCommandTime, DeviceFlag::kResponseTime, DeviceFlag::kAddresses,
    DeviceFlag::kSerialNumber, DeviceFlag::kState,        DeviceFlag::kGsd,
    DeviceFlag::kModule,      DeviceFlag::kWireTable,    DeviceFlag::kMains,
    DeviceFlag::kFDestAdd,
};

// A whole decimal number in `text`, or nullopt.
std::optional<long long> whole_number(std::string_view text) {
  long long value = 0;
  const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || p != text.data() + text.size()) return std::nullopt;
  return value;
}

int blocked_number(std::string_view item, std::string_view number) {
  const auto n = whole_number(number);
  if (!n || *n < 1 || *n > kMaxBlocked) {
    throw UsageError("--blocked: '" + std::string(item) + "': '" + std::string(number) +
                     "' is not a number 1.." + std::to_string(kMaxBlocked) +
                     " (numbers start at 1; e.g. 9-13,25-34)");
  }
  return static_cast<int>(*n);
}

}  // namespace

const char* flag_name(DeviceFlag f) {
  switch (f) {
    case DeviceFlag::kAddress: return "--address";
    case DeviceFlag::kGsd: return "--gsd";
    case DeviceFlag::kModule: return "--module";
    case DeviceFlag::kFDestAdd: return "--f-dest-add";
    case DeviceFlag::kAddresses: return "--address (repeated)";
    case DeviceFlag::kIdent: return "--ident";
    case DeviceFlag::kCfg: return "--cfg";
    case DeviceFlag::kBootTime: return "--boot-time";
    case DeviceFlag::kCommandTime: return "--command-time";
    case DeviceFlag::kResponseTime: return "--adapter-response-time";
    case DeviceFlag::kBaud: return "--baud";
    case DeviceFlag::kFormat: return "--format";
    case DeviceFlag::kElements: return "--elements";
    case DeviceFlag::kBeams: return "--beams";
    case DeviceFlag::kModel: return "--model";
    case DeviceFlag::kMode: return "--mode";
    case DeviceFlag::kBlocked: return "--blocked";
    case DeviceFlag::kDoor: return "--door";
    case DeviceFlag::kNode: return "--node";
    case DeviceFlag::kRs232: return "--rs232";
    case DeviceFlag::kPcAdapter: return "--pc-adapter";
    case DeviceFlag::kSerialNumber: return "--serial-number";
    case DeviceFlag::kState: return "--state";
    case DeviceFlag::kWireTable: return "--wire-table";
    case DeviceFlag::kMains: return "--mains";
  }
  return "--?";
}

namespace {

template <typename Used>
void refuse_flags(const DeviceOptions& o, std::string_view device, const Used& used) {
  for (const DeviceFlag f : kAllFlags) {
    if (!given(o, f) || used(f)) continue;
    if (f == DeviceFlag::kAddresses) {
      throw UsageError("--address given " + std::to_string(o.more_addresses.size() + 1) +
                       " times: --device " + std::string(device) +
                       " is one station; only --device rs4 runs several on one link");
    }
    throw UsageError(std::string(flag_name(f)) + " is not an option of --device " +
                     std::string(device));
  }
}

}  // namespace

void refuse_unused(const DeviceOptions& o, const std::string& device,
                   std::initializer_list<DeviceFlag> used) {
  refuse_flags(o, device, [used](DeviceFlag f) {
    return std::find(used.begin(), used.end(), f) != used.end();
  });
}

void refuse_unused(const DeviceOptions& o, std::string_view device,
                   std::span<const stream::OptionInfo> used) {
  refuse_flags(o, device, [used](DeviceFlag f) {
    const bool repeated = f == DeviceFlag::kAddresses;
    const std::string_view name = repeated ? "--address" : flag_name(f);
    return std::any_of(used.begin(), used.end(), [&](const stream::OptionInfo& i) {
      return i.flag == name && (!repeated || i.repeats);
    });
  });
}

std::string option_help(std::string_view flag) {
  std::string out;
  for (const DeviceEntry& e : device_registry()) {
    for (const stream::OptionInfo& i : e.options) {
      if (i.flag != flag) continue;
      out += (out.empty() ? "" : "; ") + e.name + ": " + std::string(i.help);
      if (i.min <= i.max) out += " (" + std::to_string(i.min) + ".." + std::to_string(i.max) + ")";
    }
  }
  return out;
}

std::vector<int> parse_blocked(const std::string& text) {
  std::vector<int> out;
  std::string_view rest = text;
  while (true) {
    const auto comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    if (item.empty()) {
      throw UsageError("--blocked '" + text + "': an empty item (use e.g. 9-13,25-34)");
    }
    const auto dash = item.find('-');
    const int first = blocked_number(item, item.substr(0, dash));
    const int last =
        dash == std::string_view::npos ? first : blocked_number(item, item.substr(dash + 1));
    if (last < first) {
      throw UsageError("--blocked: '" + std::string(item) + "' runs backwards (write " +
                       std::to_string(last) + "-" + std::to_string(first) + ")");
    }
    for (int n = first; n <= last; ++n) out.push_back(n);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void check_blocked(const DeviceOptions& o, int count, const std::string& what) {
  if (o.blocked && !o.blocked->empty() && o.blocked->back() > count) {
    throw UsageError("--blocked: " + std::to_string(o.blocked->back()) + " is above the " +
                     std::to_string(count) + " " + what + " (numbers 1.." + std::to_string(count) +
                     ")");
  }
}

std::uint32_t parse_bit_rate(const std::string& text) {
  const auto n = whole_number(text);
  if (!n || *n < kMinBitRate || *n > kMaxBitRate) {
    throw UsageError("--baud " + text + ": a byte device takes a plain bit rate " +
                     std::to_string(kMinBitRate) + ".." + std::to_string(kMaxBitRate) +
                     ", e.g. 19200");
  }
  return static_cast<std::uint32_t>(*n);
}

stream::LineSettings line_settings(const DeviceOptions& o, stream::LineSettings defaults) {
  if (o.baud) defaults.baud = *o.baud;
  if (!o.format.empty() && !stream::parse_format(o.format, defaults)) {
    throw UsageError("--format " + o.format +
                     ": expected data bits 5..8, parity N/E/O and stop bits 1..2, e.g. 8E1");
  }
  return defaults;
}

}  // namespace rs4sim::app
