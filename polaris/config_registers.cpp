#include "polaris/config_registers.h"

#include <array>
#include <chrono>

namespace rs4sim::polaris {

namespace {

struct Range {
  std::uint16_t min = 0;
  std::uint16_t max = 0;
  bool writable = true;
};

// Per register, in address order (docs/polaris.md "Configuration registers").
constexpr std::array<Range, kConfigRegisterCount> kRanges{{
    {0, 3},                            // data mode
    {kMinSlaveStart, kMaxSlaveStart},  // start address [Polaris manual §7.4.2]
    {0, 1},                            // direction
    {0, 1},                            // detection
    {1, 255},                          // PN2 filter [Polaris manual §7.4.2]
    {5, 5000},                         // scan time, ms [Polaris manual §7.4.2]
    {0, 1},                            // bit order
    {0, 1},                            // NAK mode
    {0, 2},                            // command
    {0, 2, false},                     // status
    {0, 0xFFFF, false},                // calibrations completed
    {0, 0xFFFF, false},                // beams
}};

std::size_t index_of(std::uint16_t address) { return address - kConfigBase; }

std::uint16_t value_of(const Options& o, const CalibrationStatus& s, ConfigRegister r) {
  switch (r) {
    case ConfigRegister::kDataMode: return static_cast<std::uint16_t>(o.mode);
    case ConfigRegister::kStartAddress: return start_address(o);
    case ConfigRegister::kDirection: return static_cast<std::uint16_t>(o.direction);
    case ConfigRegister::kDetection: return static_cast<std::uint16_t>(o.detection);
    case ConfigRegister::kPn2Filter: return o.pn2_filter;
    case ConfigRegister::kScanTime: return static_cast<std::uint16_t>(o.scan_time.count());
    case ConfigRegister::kBitOrder: return static_cast<std::uint16_t>(o.bit_order);
    case ConfigRegister::kNakMode: return o.nak_on_error ? 1 : 0;
    case ConfigRegister::kCommand: return 0;
    case ConfigRegister::kStatus: return s.calibrating ? 1 : (s.manual_adjustment ? 2 : 0);
    case ConfigRegister::kCalibrations: return s.completed;
    case ConfigRegister::kBeams: return o.beams;
  }
  return 0;
}

// `v` is inside the register's range.
void assign(ConfigWrite& w, ConfigRegister r, std::uint16_t v) {
  Options& o = w.options;
  switch (r) {
    case ConfigRegister::kDataMode: o.mode = static_cast<DataMode>(v); break;
    case ConfigRegister::kStartAddress: o.start_address = v; break;
    case ConfigRegister::kDirection: o.direction = static_cast<ScanDirection>(v); break;
    case ConfigRegister::kDetection: o.detection = static_cast<Detection>(v); break;
    case ConfigRegister::kPn2Filter: o.pn2_filter = v; break;
    case ConfigRegister::kScanTime: o.scan_time = std::chrono::milliseconds(v); break;
    case ConfigRegister::kBitOrder: o.bit_order = static_cast<BitOrder>(v); break;
    case ConfigRegister::kNakMode: o.nak_on_error = v != 0; break;
    case ConfigRegister::kCommand:
      w.start_calibration = w.start_calibration || v == kCommandStartCalibration;
      w.manual_adjustment = w.manual_adjustment || v == kCommandManualAdjustment;
      break;
    case ConfigRegister::kStatus:
    case ConfigRegister::kCalibrations:
    case ConfigRegister::kBeams: break;  // read-only: refused before
  }
}

}  // namespace

std::string_view to_string(ConfigError e) noexcept {
  switch (e) {
    case ConfigError::kUnknownRegister: return "register outside the configuration block";
    case ConfigError::kReadOnly: return "register is read-only";
    case ConfigError::kBadQuantity: return "register count or PDU length out of range";
    case ConfigError::kOutOfRange: return "value outside the register's range";
    case ConfigError::kInvalidOptions: return "the options would be invalid";
    case ConfigError::kBusy: return "auto-calibration in progress";
    case ConfigError::kBeamsInterrupted:
      return "beams interrupted: auto-calibration needs a free detection area";
  }
  return "unknown configuration error";
}

modbus::ExceptionCode exception_for(ConfigError e) noexcept {
  switch (e) {
    case ConfigError::kUnknownRegister:
    case ConfigError::kReadOnly: return modbus::ExceptionCode::kIllegalDataAddress;
    case ConfigError::kBadQuantity:
    case ConfigError::kOutOfRange:
    case ConfigError::kInvalidOptions: return modbus::ExceptionCode::kIllegalDataValue;
    case ConfigError::kBusy: return modbus::ExceptionCode::kServerDeviceBusy;
    case ConfigError::kBeamsInterrupted: return modbus::ExceptionCode::kServerDeviceFailure;
  }
  return modbus::ExceptionCode::kServerDeviceFailure;
}

std::error_code read_config(const Options& o, const CalibrationStatus& status,
                            std::uint16_t start, std::uint16_t quantity,
                            std::vector<std::uint16_t>& out) {
  if (quantity < 1 || quantity > modbus::kMaxReadQuantity) return ConfigError::kBadQuantity;
  if (!in_config_block(start) || quantity > kConfigEnd - start) {
    return ConfigError::kUnknownRegister;
  }
  out.clear();
  for (std::uint16_t a = start; a < start + quantity; ++a) {
    out.push_back(value_of(o, status, static_cast<ConfigRegister>(a)));
  }
  return {};
}

std::error_code write_config(const Options& current, std::uint16_t start,
                             std::span<const std::uint16_t> words, ConfigWrite& out) {
  if (words.empty() || words.size() > modbus::kMaxWriteQuantity) {
    return ConfigError::kBadQuantity;
  }
  if (!in_config_block(start) || words.size() > static_cast<std::size_t>(kConfigEnd - start)) {
    return ConfigError::kUnknownRegister;
  }
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (!kRanges[index_of(start) + i].writable) return ConfigError::kReadOnly;
  }
  ConfigWrite w{current, false, false};
  for (std::size_t i = 0; i < words.size(); ++i) {
    const Range& range = kRanges[index_of(start) + i];
    if (words[i] < range.min || words[i] > range.max) return ConfigError::kOutOfRange;
    assign(w, static_cast<ConfigRegister>(start + i), words[i]);
  }
  if (!w.options.validate().empty()) return ConfigError::kInvalidOptions;
  out = std::move(w);
  return {};
}

}  // namespace rs4sim::polaris
