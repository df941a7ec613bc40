#pragma once
// What `rs4sim master` prints while it runs (docs/master.md): a human console (one line
// per change of an RS4's DP state, PROFIsafe state/diagnosis, OSSD bit or Proxy-Request bit)
// or, with --json, one JSON object per line for every event. A plugged-in service (the
// parameter proxy) reports its own events through custom().

#include "rs4/device/rs4_master_station.h"

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rs4sim::app {

struct ReportField {
  std::string name;
  std::variant<std::int64_t, bool, std::string, std::vector<std::int64_t>> value;
};

class MasterReport {
 public:
  // `start`: the time the run began (timestamps are seconds since then).
  MasterReport(std::ostream& out, bool json, dp::TimePoint start);

  // {"event":"start", ...} / the console banner line.
  void started(const rs4::device::Rs4MasterStation& station, std::string_view link) const;
  // The events of one link call, then one console line per RS4 whose shown state changed.
  void events(const std::vector<rs4::device::Rs4MasterEvent>& events,
              const rs4::device::Rs4MasterStation& station, dp::TimePoint now);
  // An event of a plugged-in service, e.g. {"event":"proxy","step":"upload",...}.
  void custom(dp::TimePoint now, std::uint8_t address, std::string_view event,
              std::string_view text, const std::vector<ReportField>& fields) const;
  // The same for a station that is not an RS4 (a GSD slave: `label` "GSD slave").
  void custom(dp::TimePoint now, std::uint8_t address, std::string_view label,
              std::string_view event, std::string_view text, const std::vector<ReportField>& fields) const;
  // The final state of every RS4 ({"event":"stop",...} per RS4 with --json).
  void stopped(const rs4::device::Rs4MasterStation& station, dp::TimePoint now) const;

  [[nodiscard]] bool json() const { return json_; }

  // A slave that leaves data exchange because it stopped answering gets a line of its own:
  // "RS4 4 lost: no reply after 1 retry" and `hint`, the likely cause on this link (empty:
  // none), in both the console and the JSON ({"event":"lost","retries":1,"hint":"..."}).
  void explain_lost_slaves(unsigned retries, std::string hint);

 private:
  void json_event(const rs4::device::Rs4MasterEvent& e, dp::TimePoint now) const;
  void json_line(dp::TimePoint now, std::uint8_t address, std::string_view event,
                 const std::vector<ReportField>& fields) const;
  void console_line(const rs4::device::Rs4SlaveView& v, dp::TimePoint now);
  void note_dp_state(const rs4::device::DpStateChanged& e, dp::TimePoint now);
  [[nodiscard]] std::string seconds(dp::TimePoint now) const;

  std::ostream& out_;
  bool json_;
  dp::TimePoint start_;
  std::map<std::uint8_t, std::string> shown_;  // the last console line per RS4 (without time)
  std::map<std::uint8_t, bool> in_data_exchange_;
  unsigned retries_ = 0;
  std::string lost_hint_;
};

}  // namespace rs4sim::app
