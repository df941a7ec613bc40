#include "metron/wire_table.h"

#include "metron/enum_table.h"

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

constexpr std::array<std::string_view, kReplyFieldCount> kReplyFieldNames{
    "start", "node", "length", "code", "data", "checksum"};
constexpr std::array<std::string_view, kReportFieldCount> kReportFieldNames{"start", "data",
                                                                            "checksum", "end"};

constexpr std::array<std::string_view, kStopItemCount> kStopItemNames{"code", "maximum"};
constexpr std::array<std::string_view, kConfigItemCount> kConfigItemNames{
    "beams", "input_type", "node", "scan_cycle", "t_response"};
constexpr std::array<std::string_view, kStatusFlagCount> kStatusFlagNames{
    "synchronised", "ossd_enabled", "ossd_standby", "ossd_measuring",
    "measuring",    "interrupted",  "input_high"};

template <class E>
bool has_duplicate(const std::vector<E>& items) {
  for (std::size_t i = 0; i < items.size(); ++i)
    if (std::count(items.begin(), items.end(), items[i]) > 1) return true;
  return false;
}

std::string quoted(std::string_view s) { return "\"" + std::string(s) + "\""; }

// The first field of `set` that `fields` does not list, if any.
std::optional<ReplyField> outside(ReplyFieldSet set, const std::vector<ReplyField>& fields) {
  for (std::size_t i = 0; i < kReplyFieldCount; ++i) {
    const auto f = static_cast<ReplyField>(i);
    if (contains(set, f) && std::find(fields.begin(), fields.end(), f) == fields.end()) return f;
  }
  return std::nullopt;
}

std::optional<WireIssue> check_reply(const ReplyLayout& r) {
  for (std::size_t i = 0; i < r.fields.size(); ++i) {
    if (static_cast<std::size_t>(r.fields[i]) >= kReplyFieldCount)
      return WireIssue{"reply.fields", "the reply names an unknown field"};
    if (std::find(r.fields.begin(), r.fields.begin() + static_cast<std::ptrdiff_t>(i),
                  r.fields[i]) != r.fields.begin() + static_cast<std::ptrdiff_t>(i))
      return WireIssue{"reply.fields",
                       "the reply lists " + quoted(to_token(r.fields[i])) + " twice"};
  }
  if (std::find(r.fields.begin(), r.fields.end(), ReplyField::kData) == r.fields.end())
    return WireIssue{"reply.fields", "a reply needs \"data\" (what the requests ask for)"};
  if (std::find(r.fields.begin(), r.fields.end(), ReplyField::kCode) == r.fields.end())
    return WireIssue{"reply.fields",
                     "a reply needs \"code\" (without it E1..E5 and an empty answer look alike)"};
  if (r.length_counts >= (1U << kReplyFieldCount) || r.checksum_covers >= (1U << kReplyFieldCount))
    return WireIssue{"reply", "a reply field set names an unknown field"};
  if (const auto f = outside(r.length_counts, r.fields))
    return WireIssue{"reply.length_counts", "the Length byte counts " + quoted(to_token(*f)) +
                                                ", which the reply does not carry"};
  if (const auto f = outside(r.checksum_covers, r.fields))
    return WireIssue{"reply.checksum_covers", "the checksum covers " + quoted(to_token(*f)) +
                                                  ", which the reply does not carry"};
  if (contains(r.checksum_covers, ReplyField::kChecksum))
    return WireIssue{"reply.checksum_covers", "the checksum cannot sum itself"};
  return std::nullopt;
}

std::optional<WireIssue> check_report(const ReportLayout& r) {
  for (std::size_t i = 0; i < kReportFieldCount; ++i) {
    if (std::count(r.order.begin(), r.order.end(), static_cast<ReportField>(i)) != 1)
      return WireIssue{"report.order",
                       "the report order must list \"start\", \"data\", \"checksum\" and \"end\" "
                       "once each (Table 1: one character before and one after "
                       "the data, one checksum character)"};
  }
  return std::nullopt;
}

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

std::optional<WireIssue> check_replies(const ReplyData& r) {
  if (r.stop_measurement.empty() || has_duplicate(r.stop_measurement))
    return WireIssue{"replies.stop_measurement",
                     "#8 must return \"code\" and/or \"maximum\", each once"};
  if (r.beam_interrupted == r.beam_free)
    return WireIssue{"replies.beam_free", "a free beam must differ from an interrupted one"};
  if (r.configuration.empty() || has_duplicate(r.configuration))
    return WireIssue{"replies.configuration", "#11 must return at least one item, each once"};
  std::uint8_t seen = 0;
  for (const std::uint8_t mask : r.curtain_status) {
    if (mask == 0) continue;
    if ((mask & (mask - 1U)) != 0 || (seen & mask) != 0)
      return WireIssue{"replies.curtain_status",
                       "each flag takes its own single bit (or 0: not reported), not " + hex(mask)};
    seen = static_cast<std::uint8_t>(seen | mask);
  }
  return std::nullopt;
}

}  // namespace

std::string_view to_token(StopItem i) { return kStopItemNames[static_cast<std::size_t>(i)]; }
std::string_view to_token(ConfigItem i) { return kConfigItemNames[static_cast<std::size_t>(i)]; }
std::string_view to_token(StatusFlag f) { return kStatusFlagNames[static_cast<std::size_t>(f)]; }
std::optional<StopItem> parse_stop_item(std::string_view t) {
  return enum_of_entry<StopItem>(kStopItemNames, t);
}
std::optional<ConfigItem> parse_config_item(std::string_view t) {
  return enum_of_entry<ConfigItem>(kConfigItemNames, t);
}
std::optional<StatusFlag> parse_status_flag(std::string_view t) {
  return enum_of_entry<StatusFlag>(kStatusFlagNames, t);
}

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

std::string_view to_token(ReplyField f) { return kReplyFieldNames[static_cast<std::size_t>(f)]; }
std::string_view to_token(ReportField f) { return kReportFieldNames[static_cast<std::size_t>(f)]; }

std::optional<ReplyField> parse_reply_field(std::string_view token) {
  for (std::size_t i = 0; i < kReplyFieldCount; ++i)
    if (kReplyFieldNames[i] == token) return static_cast<ReplyField>(i);
  return std::nullopt;
}

std::optional<ReportField> parse_report_field(std::string_view token) {
  for (std::size_t i = 0; i < kReportFieldCount; ++i)
    if (kReportFieldNames[i] == token) return static_cast<ReportField>(i);
  return std::nullopt;
}

std::optional<WireIssue> check(const WireTable& t) {
  if (!all_distinct(t.commands)) return WireIssue{"commands", "two commands share a code"};
  if (!all_distinct(t.errors)) return WireIssue{"errors", "two error answers share a code"};
  for (const auto e : t.errors)
    if (std::find(t.commands.begin(), t.commands.end(), e) != t.commands.end())
      return WireIssue{"errors", "error answer code " + hex(e) + " is also a command code"};
  if (!all_distinct(t.measurements))
    return WireIssue{"measurements", "two measurements share a code"};
  if (t.all_beams != 0 && t.all_beams != 0xFF)
    return WireIssue{"all_beams",
                     "the all-beams selector must be 0x00 or 0xFF (beam numbers use the rest)"};
  if (t.report_start == t.report_end)
    return WireIssue{"report_end", "report start and end are equal"};
  if (t.separator == t.report_start || t.separator == t.report_end)
    return WireIssue{"separator", "the separator " + hex(t.separator) +
                                      " is also the report's start or end character"};
  if (auto r = check_reply(t.reply)) return r;
  if (auto r = check_replies(t.replies)) return r;
  return check_report(t.report);
}

std::string validate(const WireTable& t) {
  const auto issue = check(t);
  return issue ? "wire table: " + issue->reason : std::string{};
}

}  // namespace rs4sim::metron
