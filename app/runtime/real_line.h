#pragma once
// A real line you can trust (docs/serial.md): the loop thread under SCHED_FIFO with locked
// memory (`--rt-priority`), and the end-of-run report of the replies' turnaround per station
// (dp/link/turnaround.h) in text or as JSON lines (`--json`), with the replies held back by
// `--tsl`.

#include "dp/link/turnaround.h"

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

namespace rs4sim::app {

// SCHED_FIFO at `priority` (1..99) for the calling thread and mlockall(MCL_CURRENT |
// MCL_FUTURE) for the process. Empty on success, else the reason and what to do (EPERM:
// CAP_SYS_NICE or `ulimit -r`; ENOMEM/EPERM of mlockall: `ulimit -l`).
[[nodiscard]] std::string enter_realtime(int priority);
// The message for a failed step (`sched_setscheduler` or `mlockall`) with `err` (errno), for
// enter_realtime() and its tests.
[[nodiscard]] std::string realtime_error(const std::string& step, int priority, int err);

// "turnaround 5: 1204 replies, p50 0.112 ms, p99 0.410 ms, max 1.877 ms, mean 0.130 ms;
// late (> TSL 8.000 ms, not sent) 0" and, when a reply was timed, a second line with the
// non-empty histogram buckets by their exclusive upper bound in µs ("  histogram (µs):
// < 114.688: 1180, < 131.072: 20, ..."; the last bucket, without a bound, as
// ">= 34359738.368: N") or, with
// `json`, one object per line:
// {"event":"turnaround","address":5,"replies":1204,"late":0,"p50_us":112.6,...,
//  "histogram":[{"le_us":1.28,"count":3},...]} (the non-empty buckets, by upper bound).
void print_turnaround(std::ostream& out, std::uint8_t address, const dp::link::TurnaroundStats& s,
                      std::optional<std::int64_t> tsl_us, bool json);

}  // namespace rs4sim::app
