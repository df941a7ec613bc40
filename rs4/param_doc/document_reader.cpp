#include "json/message.h"
#include "rs4/param_doc/contour_reader.h"
#include "rs4/param_doc/json_tree.h"
#include "rs4/param_doc/parameter_document.h"
#include "rs4/report/parameter_fields.h"

#include <array>
#include <optional>

namespace rs4sim::rs4::param_doc {
namespace {

using json::Value;
using scanner::ParameterSet;

constexpr std::int64_t kMinResponseMs = 80;  // [RS4 manual §6.6] "minimal 80 ms"
constexpr std::int64_t kResponseStepMs = 40;
constexpr std::int64_t kMaxResponseMs =
    kMinResponseMs + kResponseStepMs * scanner::kMaxResponseSteps;
constexpr ContourLimit kProtectiveLimit{scanner::kMaxProtectiveMm,
                                        "(protective field limit [RS4 manual §2.3])"};
constexpr ContourLimit kWarningLimit{scanner::kMaxWarningMm,
                                     "(warning field limit, docs/rs4-scanner.md)"};

void read_response_time(const Value& v, ParameterSet& set) {
  const std::string path = "$.response_time_ms";
  const auto ms = json::integer(v, path, kMinResponseMs, kMaxResponseMs,
                                "ms (80 ms + n·40 ms [RS4 manual §6.6])");
  if ((ms - kMinResponseMs) % kResponseStepMs != 0) {
    json::refuse(DocumentError::kOutOfRange, path,
                 std::to_string(ms) + " is not 80 + n·40 ms (80, 120, ..., 640) [RS4 manual §6.6]");
  }
  set.response_steps = static_cast<std::uint8_t>((ms - kMinResponseMs) / kResponseStepMs);
}

void read_restart_mode(const Value& v, ParameterSet& set) {
  const std::string path = "$.restart_mode";
  const std::string& name = json::text(v, path);
  constexpr std::array kModes{scanner::RestartMode::kAutomatic,
                              scanner::RestartMode::kStartInterlock,
                              scanner::RestartMode::kStartRestartInterlock};
  for (const auto mode : kModes) {
    if (report::restart_mode_name(mode) == name) {
      set.restart_mode = mode;
      return;
    }
  }
  json::refuse(DocumentError::kOutOfRange, path,
               "\"" + rs4sim::json::cut(name) +
                   "\" is not automatic, start_interlock or start_restart_interlock "
                   "([RS4 manual §4.3])");
}

std::uint8_t read_pair_number(const Value& v, const std::string& path) {
  return static_cast<std::uint8_t>(
      json::integer(v, path, 1, scanner::kFieldPairCount, "(field pair)"));
}

void check_pair_key(const std::string& key, const std::string& path) {
  if (key.size() != 1 || key[0] < '1' || key[0] > '4') {
    json::refuse(DocumentError::kUnknownKey, path, "field pairs are \"1\" to \"4\"");
  }
}

void read_permitted(const Value& v, ParameterSet& set) {
  const std::string path = "$.permitted";
  for (const auto& [key, row] : json::object(v, path).fields()) {
    const std::string at = json::key_path(path, key);
    check_pair_key(key, at);
    const auto& targets = json::list(row, at);
    std::uint8_t mask = 0;
    for (int i = 0; i < targets.values_size(); ++i) {
      const auto to =
          read_pair_number(targets.values(i), json::index_path(at, static_cast<std::size_t>(i)));
      mask = static_cast<std::uint8_t>(mask | (1U << (to - 1U)));
    }
    set.permitted[static_cast<std::size_t>(key[0] - '1')] = mask;
  }
}

void read_warning_output(const Value& v, ParameterSet& set) {
  const std::string path = "$.warning_output";
  const auto& sources = json::list(v, path);
  std::uint8_t mask = 0;
  for (int i = 0; i < sources.values_size(); ++i) {
    const std::string at = json::index_path(path, static_cast<std::size_t>(i));
    const std::string& name = json::text(sources.values(i), at);
    unsigned bit = 0;
    while (bit < 4 &&
           report::warning_output_names(static_cast<std::uint8_t>(1U << bit))[0] != name) {
      ++bit;
    }
    if (bit == 4) {
      json::refuse(DocumentError::kOutOfRange, at,
                   "\"" + rs4sim::json::cut(name) +
                       "\" is not contamination, warning_field, fault or restart_interlock "
                       "([RS4 manual §5.1.1])");
    }
    mask = static_cast<std::uint8_t>(mask | (1U << bit));
  }
  set.warning_output = mask;
}

void read_measurement(const Value& v, ParameterSet& set) {
  const std::string path = "$.measurement";
  const auto& o = json::object(v, path);
  json::check_keys(o, path, {"resolution", "start", "stop"});
  const std::string_view what = "([RS4 manual §5.2.3.4])";
  if (const Value* r = json::find(o, "resolution")) {
    set.measurement.resolution = static_cast<std::uint8_t>(
        json::integer(*r, json::key_path(path, "resolution"), 1, 255, what));
  }
  if (const Value* s = json::find(o, "start")) {
    set.measurement.start = static_cast<std::uint16_t>(
        json::integer(*s, json::key_path(path, "start"), 0, scanner::kSegmentCount - 1, what));
  }
  if (const Value* s = json::find(o, "stop")) {
    set.measurement.stop = static_cast<std::uint16_t>(
        json::integer(*s, json::key_path(path, "stop"), 0, scanner::kSegmentCount - 1, what));
  }
}

// Per pair, the protective segments the document's runs leave unset (none: the document
// gives no protective contour for the pair): checked once the set is whole.
using GivenFields = std::array<std::optional<std::size_t>, scanner::kFieldPairCount>;

void read_pairs(const Value& v, ParameterSet& set, GivenFields& given) {
  const std::string path = "$.pairs";
  for (const auto& [key, pair] : json::object(v, path).fields()) {
    const std::string at = json::key_path(path, key);
    check_pair_key(key, at);
    auto& target = set.pairs[static_cast<std::size_t>(key[0] - '1')];
    const auto& o = json::object(pair, at);
    json::check_keys(o, at, {"protective", "warning"});
    if (const Value* c = json::find(o, "protective")) {
      std::size_t unset = 0;
      target.protective_mm =
          read_contour(*c, json::key_path(at, "protective"), kProtectiveLimit, unset);
      given[static_cast<std::size_t>(key[0] - '1')] = unset;
    }
    if (const Value* c = json::find(o, "warning")) {
      std::size_t unset = 0;  // a warning field may leave segments out
      target.warning_mm = read_contour(*c, json::key_path(at, "warning"), kWarningLimit, unset);
    }
  }
}

void read_format(const json::Object& root) {
  const Value* format = json::find(root, "format");
  if (format == nullptr) {
    json::refuse(DocumentError::kMissingKey, "$.format", "required (1)");
  }
  const double number = json::number(*format, "$.format");
  if (number != kDocumentFormat) {
    json::refuse(DocumentError::kUnsupportedFormat, "$.format",
                 "this rs4sim reads format " + std::to_string(kDocumentFormat));
  }
}

// The JSON path of the document value a scanner::ValidationIssue is about.
std::string path_of(const scanner::ValidationIssue& issue) {
  const std::string pair = std::to_string(issue.pair);
  if (issue.field == "response_steps") return "$.response_time_ms";
  if (issue.field == "permitted") return "$.permitted." + pair;
  if (issue.field == "pairs[].protective_mm") return "$.pairs." + pair + ".protective";
  if (issue.field == "pairs[].warning_mm") return "$.pairs." + pair + ".warning";
  if (issue.field == "passwords[]") return "$";  // the base set's, never the document's
  return "$." + std::string(issue.field);
}

void check_given_fields(const GivenFields& given, const CoverageOptions& options) {
  for (std::size_t p = 0; p < given.size(); ++p) {
    if (!given[p]) continue;
    const auto path = "$.pairs." + std::to_string(p + 1) + ".protective.runs";
    if (auto issue = check_protective_field(*given[p], path, options)) {
      json::refuse(issue->error, issue->path, issue->reason);
    }
  }
}

ParameterSet read_document(std::string_view text, const ParameterSet& base,
                           const CoverageOptions& coverage) {
  const Value root_value = json::parse(text);
  const auto& root = json::object(root_value, "$");
  json::check_keys(root, "$",
                   {"format", "device", "response_time_ms", "restart_mode", "start_pair",
                    "permitted", "warning_output", "measurement", "pairs"});
  read_format(root);
  if (const Value* d = json::find(root, "device")) json::object(*d, "$.device");  // read-only
  ParameterSet set = base;
  if (const Value* v = json::find(root, "response_time_ms")) read_response_time(*v, set);
  if (const Value* v = json::find(root, "restart_mode")) read_restart_mode(*v, set);
  if (const Value* v = json::find(root, "start_pair")) {
    set.start_pair = read_pair_number(*v, "$.start_pair");
  }
  if (const Value* v = json::find(root, "permitted")) read_permitted(*v, set);
  if (const Value* v = json::find(root, "warning_output")) read_warning_output(*v, set);
  if (const Value* v = json::find(root, "measurement")) read_measurement(*v, set);
  GivenFields given{};
  if (const Value* v = json::find(root, "pairs")) read_pairs(*v, set, given);
  if (const auto issue = scanner::validate(set)) {
    json::refuse(DocumentError::kInvalidSet, path_of(*issue), issue->message());
  }
  check_given_fields(given, coverage);
  return set;
}

}  // namespace

DocumentResult from_document(std::string_view json, const ParameterSet& base,
                             const CoverageOptions& coverage) {
  try {
    return {read_document(json, base, coverage), {}};
  } catch (const json::Refusal& refusal) {
    return {std::nullopt, refusal.issue};
  }
}

}  // namespace rs4sim::rs4::param_doc
