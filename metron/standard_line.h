#pragma once
// Standard line mode: when the Receiver composes and sends a report [METRON manual
// "Continuous reporting" .. "Input-related reporting"]. Scan cycles and periods are
// deadlines on the injected clock. A report is sent only when the previous one has
// finished (t_send of Equations 1/2, incl. the 1 ms pause); otherwise it is dropped
// (continuous, periodical, input-related) or waits for a later cycle (status change, on
// request, the three Start/Stop repeats).

#include "metron/options.h"
#include "metron/scene.h"
#include "metron/standard_report.h"
#include "stream/clock.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace rs4sim::metron {

struct Outgoing {
  stream::TimePoint at{};
  std::vector<std::uint8_t> bytes;
};

struct StandardStats {
  std::uint64_t reports = 0;
  std::uint64_t dropped = 0;  // composed while the previous report was still on the line
  std::uint64_t requests = 0;
  std::uint64_t other_bytes = 0;  // received bytes that are not the request character
};

class StandardLine {
 public:
  explicit StandardLine(const Options& options);

  void start(stream::TimePoint now);
  void on_bytes(std::span<const std::uint8_t> bytes);
  // The input changed level (edges drive Start/Stop); the scene is the one after the change.
  void on_input(bool high, const Scene& scene);
  void on_scene(const Scene& scene);
  // Runs every cycle and period up to `now`; reports go to `out` stamped with their cycle.
  void advance(stream::TimePoint now, const Scene& scene, std::vector<Outgoing>& out);
  [[nodiscard]] std::optional<stream::TimePoint> deadline() const;
  [[nodiscard]] const StandardStats& stats() const { return stats_; }

 private:
  void cycle(stream::TimePoint t, const Scene& scene, std::vector<Outgoing>& out);
  void input_related(stream::TimePoint t, const Scene& scene, std::vector<Outgoing>& out);
  bool send(stream::TimePoint t, std::vector<std::uint8_t> bytes, std::vector<Outgoing>& out);
  bool send_scene(stream::TimePoint t, const Scene& scene, std::vector<Outgoing>& out);
  [[nodiscard]] std::vector<std::uint8_t> compose(const Scene& scene) const;
  [[nodiscard]] bool busy(stream::TimePoint t) const { return t < busy_until_; }

  const Options& o_;
  ReportFormat format_;
  stream::LineSettings line_;
  std::optional<stream::TimePoint> next_cycle_;
  std::optional<stream::TimePoint> next_period_;
  stream::TimePoint busy_until_{};
  std::vector<std::uint8_t> last_sent_;
  std::optional<std::vector<std::uint8_t>> last_beams_;  // status change: beams at last report
  bool request_pending_ = false;
  bool tracking_ = false;
  std::uint8_t maximum_ = 0;
  int repeats_left_ = 0;
  StandardStats stats_;
};

}  // namespace rs4sim::metron
