#include "metron/wire_table.h"

#include <algorithm>
#include <cstdio>

namespace rs4sim::metron {
namespace {

constexpr std::array<std::string_view, kCommandCount> kCommandNames{
    "Reset software",
    "Enable OSSD",
    "Disable OSSD",
    "OSSD stand-by",
    "Start OSSD measurement",
    "Stop OSSD measurement",
    "Start measurement",
    "Stop measurement",
    "Request active beam status",
    "Request instantaneous measurements",
    "Request configuration",
    "Request OSSD status",
    "Request light curtain status"};

constexpr std::array<std::string_view, kMeasurementCount> kMeasurementNames{
    "first", "last", "count", "free", "central", "run"};

template <std::size_t N>
bool all_distinct(const std::array<std::uint8_t, N>& a) {
  auto s = a;
  std::sort(s.begin(), s.end());
  return std::adjacent_find(s.begin(), s.end()) == s.end();
}

std::string hex(std::uint8_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", v);
  return buf;
}

}  // namespace

std::optional<Command> command_from_code(const WireTable& t, std::uint8_t code) {
  for (std::size_t i = 0; i < kCommandCount; ++i)
    if (t.commands[i] == code) return static_cast<Command>(i);
  return std::nullopt;
}

std::optional<Measurement> measurement_from_code(const WireTable& t, std::uint8_t code) {
  for (std::size_t i = 0; i < kMeasurementCount; ++i)
    if (t.measurements[i] == code) return static_cast<Measurement>(i);
  return std::nullopt;
}

std::string_view to_string(Command c) { return kCommandNames[static_cast<std::size_t>(c)]; }

std::string_view to_string(ErrorCase e) {
  switch (e) {
    case ErrorCase::kE1: return "E1 (checksum wrong or length > 6)";
    case ErrorCase::kE2: return "E2 (length or argument wrong)";
    case ErrorCase::kE3: return "E3 (OSSD state does not allow it)";
    case ErrorCase::kE4: return "E4 (synchronism missing)";
    case ErrorCase::kE5: return "E5 (no Start measurement before)";
  }
  return "?";
}

std::string_view to_string(Measurement m) { return kMeasurementNames[static_cast<std::size_t>(m)]; }

std::optional<Measurement> parse_measurement(std::string_view name) {
  for (std::size_t i = 0; i < kMeasurementCount; ++i)
    if (kMeasurementNames[i] == name) return static_cast<Measurement>(i);
  return std::nullopt;
}

std::string validate(const WireTable& t) {
  if (!all_distinct(t.commands)) return "wire table: two commands share a code";
  if (!all_distinct(t.errors)) return "wire table: two error answers share a code";
  for (const auto e : t.errors)
    if (std::find(t.commands.begin(), t.commands.end(), e) != t.commands.end())
      return "wire table: error answer code " + hex(e) + " is also a command code";
  if (!all_distinct(t.measurements)) return "wire table: two measurements share a code";
  if (t.all_beams != 0 && t.all_beams != 0xFF)
    return "wire table: the all-beams selector must be 0x00 or 0xFF (beam numbers use the rest)";
  if (t.report_start == t.report_end) return "wire table: report start and end are equal";
  return {};
}

}  // namespace rs4sim::metron
