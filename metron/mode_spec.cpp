#include "metron/mode_spec.h"

#include "stream/words.h"

#include <charconv>
#include <optional>
#include <vector>

namespace rs4sim::metron {
namespace {

using stream::split_words;

std::string apply_report(std::string_view list, Options& o) {
  o.report.clear();
  for (const auto name : split_words(list, '+')) {
    const auto m = parse_measurement(name);
    if (!m) return "unknown measurement '" + std::string(name) + "' in report=";
    o.report.push_back(*m);
  }
  return {};
}

// "key=<ms>" into `out`; "" or what is wrong.
std::string read_ms(std::string_view word, std::size_t key_size, stream::Duration& out,
                    std::string_view help) {
  const auto v = word.substr(key_size);
  int ms = 0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), ms);
  if (v.empty() || r.ec != std::errc{} || r.ptr != v.data() + v.size()) return std::string(help);
  out = std::chrono::milliseconds(ms);
  return {};
}

// The words both line modes take: the input type and the timing (Equation 3's t_response
// and the scan cycle [METRON manual "Slave line mode"]): "" or what is wrong; nullopt when
// the word is none of them.
std::optional<std::string> apply_common(std::string_view word, Options& o) {
  if (word.starts_with("input=")) {
    const auto t = parse_input_type(word.substr(6));
    if (!t) return "unknown input type '" + std::string(word.substr(6)) + "'";
    o.input_type = *t;
    return std::string{};
  }
  if (word.starts_with("scan-cycle="))
    return read_ms(word, 11, o.scan_cycle, "scan-cycle= takes milliseconds, e.g. scan-cycle=10");
  if (word.starts_with("t-response="))
    return read_ms(word, 11, o.t_response, "t-response= takes milliseconds, e.g. t-response=20");
  return std::nullopt;
}

std::string apply_option(std::string_view word, Options& o) {
  if (auto e = apply_common(word, o)) return *e;
  if (const auto f = parse_format(word)) {
    o.format = *f;
    return {};
  }
  if (word == "separator") {
    o.separator = true;
    return {};
  }
  if (word == "checksum") {
    o.checksum = true;
    return {};
  }
  if (word.starts_with("period=")) {
    const auto v = word.substr(7);
    int ms = 0;
    const auto r = std::from_chars(v.data(), v.data() + v.size(), ms);
    if (r.ec != std::errc{} || r.ptr != v.data() + v.size())
      return "period= takes milliseconds, e.g. period=250";
    o.period = std::chrono::milliseconds(ms);
    return {};
  }
  if (word.starts_with("report=")) return apply_report(word.substr(7), o);
  return "unknown mode option '" + std::string(word) + "'";
}

}  // namespace

std::string apply_mode_spec(std::string_view spec, Options& o) {
  const auto words = split_words(spec, ',');
  if (words.front() == "slave") {
    // The input type applies in both modes: in slave mode it decides whether the host may
    // drive the OSSDs (#2..#6 need No_function) [METRON manual "Slave line mode"].
    for (std::size_t i = 1; i < words.size(); ++i) {
      const auto e = apply_common(words[i], o);
      if (!e) {
        return "slave mode takes only input=<type>, scan-cycle=<ms> and t-response=<ms> "
               "(19200 8E1 binary, fixed)";
      }
      if (!e->empty()) return *e;
    }
    o.line_mode = LineMode::kSlave;
    return {};
  }
  const auto mode = parse_reporting_mode(words.front());
  if (!mode)
    return "mode must be slave, continuous, periodical, on-request, status-change or "
           "input-related, not '" +
           std::string(words.front()) + "'";
  o.line_mode = LineMode::kStandard;
  o.reporting_mode = *mode;
  for (std::size_t i = 1; i < words.size(); ++i)
    if (auto e = apply_option(words[i], o); !e.empty()) return e;
  return {};
}

}  // namespace rs4sim::metron
