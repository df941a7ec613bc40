#include "polaris/options.h"

#include "modbus/rtu_frame.h"

#include <array>
#include <span>

namespace rs4sim::polaris {

namespace {

constexpr std::array<std::string_view, 4> kModeNames{"485MB", "FL1", "FL4", "FL10"};
constexpr std::array<DataMode, 4> kModes{DataMode::k485Mb, DataMode::kFl1, DataMode::kFl4,
                                         DataMode::kFl10};
constexpr std::array<std::uint32_t, 4> kBauds{19200, 38400, 57600, 115200};
constexpr std::chrono::milliseconds kMinScanTime{5};
constexpr std::chrono::milliseconds kMaxScanTime{5000};
constexpr std::uint16_t kMaxFilter = 255;

std::string check_beams(const Options& o) {
  for (const auto b : o.blocked) {
    if (b < 1 || b > o.beams)
      return "blocked beam " + std::to_string(b) + " outside 1.." + std::to_string(o.beams);
  }
  if (height_for_beams(o.family, o.beams)) return {};
  const BeamRange r = beam_range(o.family);
  return "beams " + std::to_string(o.beams) + ": no " + std::string(to_string(o.family)) +
         " model has that many (the family makes " + std::to_string(r.min) + ".." +
         std::to_string(r.max) + " beams, by its body heights)";
}

std::string check_line(const Options& o) {
  for (const std::uint32_t b : kBauds) {
    if (b == o.baud) return {};
  }
  return "baud " + std::to_string(o.baud) + ": the Polaris runs at 19200, 38400, 57600 or 115200";
}

std::string check_addresses(const Options& o) {
  if (!modbus::is_slave_address(o.address)) {
    return "address " + std::to_string(o.address) + ": must be " +
           std::to_string(modbus::kMinSlaveAddress) + ".." +
           std::to_string(modbus::kMaxSlaveAddress) + " (no broadcast)";
  }
  const std::uint16_t start = start_address(o);
  if (o.role == Role::kSlave && (start < kMinSlaveStart || start > kMaxSlaveStart)) {
    return "start address " + std::to_string(start) + ": must be 500..12287 in slave mode";
  }
  return {};
}

std::string check_timing(const Options& o) {
  if (o.scan_time < kMinScanTime || o.scan_time > kMaxScanTime) {
    return "scan time " + std::to_string(o.scan_time.count()) + " ms: must be 5..5000 ms";
  }
  if (o.pn2_filter < 1 || o.pn2_filter > kMaxFilter) {
    return "PN2 filter " + std::to_string(o.pn2_filter) + ": must be 1..255 scans";
  }
  if (o.response_time < stream::Duration::zero() || o.response_time > kMaxResponseTime) {
    return "response time " +
           std::to_string(std::chrono::duration_cast<std::chrono::microseconds>(o.response_time)
                              .count()) +
           " us: must be 0 (the model's) .. 1000 ms";
  }
  if (o.response_column != ResponseColumn::kFirst && o.response_column != ResponseColumn::kSecond) {
    return "response column " + std::to_string(static_cast<int>(o.response_column)) +
           ": the model tables have columns 1 and 2";
  }
  return {};
}

}  // namespace

std::string_view to_string(DataMode m) noexcept {
  return kModeNames.at(static_cast<std::size_t>(m));
}

std::optional<DataMode> parse_data_mode(std::string_view text) noexcept {
  for (std::size_t i = 0; i < kModes.size(); ++i) {
    if (kModeNames[i] == text) return kModes[i];
  }
  return std::nullopt;
}

std::string_view to_token(DataStorage s) noexcept {
  switch (s) {
    case DataStorage::kNone: return "none";
    case DataStorage::kObject: return "object";
    case DataStorage::kHole: return "hole";
  }
  return "none";
}

std::optional<DataStorage> parse_data_storage(std::string_view text) noexcept {
  for (const DataStorage s : {DataStorage::kNone, DataStorage::kObject, DataStorage::kHole}) {
    if (to_token(s) == text) return s;
  }
  return std::nullopt;
}

std::uint16_t start_address(const Options& o) noexcept {
  if (o.start_address) return *o.start_address;
  return o.role == Role::kSlave ? kDefaultSlaveStart : 0;
}

stream::Duration scan_duration(const Options& o) noexcept {
  if (o.response_time > stream::Duration::zero()) return o.response_time;
  const auto column = [&o](const Model& m) {
    return o.response_column == ResponseColumn::kSecond ? m.response_time_2nd() : m.response_time();
  };
  const std::span<const Model> family = models(o.family);
  for (const Model& m : family) {
    if (m.beams >= o.beams) return column(m);
  }
  return column(family.back());
}

stream::LineSettings line_settings(const Options& o) noexcept {
  return stream::LineSettings{o.baud, 8, stream::Parity::kNone, 1};
}

std::string Options::validate() const {
  for (const auto check : {check_beams, check_line, check_addresses, check_timing}) {
    std::string message = check(*this);
    if (!message.empty()) return message;
  }
  return {};
}

}  // namespace rs4sim::polaris
