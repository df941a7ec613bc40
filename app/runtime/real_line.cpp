#include "app/runtime/real_line.h"

#include <sched.h>
#include <sys/mman.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ostream>

namespace rs4sim::app {

std::string realtime_error(const std::string& step, int priority, int err) {
  const std::string name = err == EPERM    ? "EPERM"
                           : err == ENOMEM ? "ENOMEM"
                                           : "errno " + std::to_string(err);
  std::string text = "--rt-priority " + std::to_string(priority) + ": " + step +
                     " failed: " + std::strerror(err) + " (" + name + ")";
  if (step == "sched_setscheduler(SCHED_FIFO)" && err == EPERM) {
    text +=
        "; a real-time priority needs CAP_SYS_NICE (e.g. sudo setcap cap_sys_nice+ep "
        "$(which rs4sim)) or a real-time limit of at least " +
        std::to_string(priority) + " (ulimit -r " + std::to_string(priority) +
        ", /etc/security/limits.conf rtprio); or run without --rt-priority";
  } else if (step == "mlockall" && (err == EPERM || err == ENOMEM)) {
    text +=
        "; locking the memory needs CAP_IPC_LOCK or a locked-memory limit large enough for "
        "the process (ulimit -l unlimited, /etc/security/limits.conf memlock); or run "
        "without --rt-priority";
  }
  return text;
}

std::string enter_realtime(int priority) {
  sched_param param{};
  param.sched_priority = priority;
  // 0: the calling thread, the loop's (threads it starts later inherit the policy).
  if (sched_setscheduler(0, SCHED_FIFO, &param) != 0) {
    return realtime_error("sched_setscheduler(SCHED_FIFO)", priority, errno);
  }
  if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
    const int err = errno;
    param.sched_priority = 0;
    (void)sched_setscheduler(0, SCHED_OTHER, &param);
    return realtime_error("mlockall", priority, err);
  }
  return {};
}

namespace {
std::string ms(std::int64_t ns) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f ms", static_cast<double>(ns) / 1e6);
  return b;
}
std::string us(std::int64_t ns) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", static_cast<double>(ns) / 1e3);
  return b;
}
}  // namespace

void print_turnaround(std::ostream& out, std::uint8_t address, const dp::link::TurnaroundStats& s,
                      std::optional<std::int64_t> tsl_us, bool json) {
  using dp::link::TurnaroundStats;
  if (json) {
    out << R"({"event":"turnaround","address":)" << int(address) << R"(,"replies":)" << s.count()
        << R"(,"late":)" << s.late() << R"(,"tsl_us":)"
        << (tsl_us ? std::to_string(*tsl_us) : "null") << R"(,"p50_us":)" << us(s.quantile_ns(0.5))
        << R"(,"p99_us":)" << us(s.quantile_ns(0.99)) << R"(,"max_us":)" << us(s.max_ns())
        << R"(,"mean_us":)" << us(s.mean_ns()) << R"(,"histogram":[)";
    bool first = true;
    for (std::size_t i = 0; i < TurnaroundStats::kBuckets; ++i) {
      if (s.buckets()[i] == 0) continue;
      out << (first ? "" : ",") << R"({"le_us":)"
          << (i + 1 == TurnaroundStats::kBuckets ? std::string("null")
                                                 : us(TurnaroundStats::bucket_upper_ns(i)))
          << R"(,"count":)" << s.buckets()[i] << "}";
      first = false;
    }
    out << "]}" << std::endl;
    return;
  }
  out << "turnaround " << int(address) << ": " << s.count() << " replies";
  if (s.count() > 0) {
    out << ", p50 " << ms(s.quantile_ns(0.5)) << ", p99 " << ms(s.quantile_ns(0.99)) << ", max "
        << ms(s.max_ns()) << ", mean " << ms(s.mean_ns());
  }
  if (tsl_us) {
    out << "; late (> TSL " << ms(*tsl_us * 1000) << ", not sent) " << s.late();
  }
  out << std::endl;
  if (s.count() == 0) return;
  // The non-empty buckets by their exclusive upper bound in µs (ms at 3 decimals would give
  // neighbouring buckets the same name); the last one (no bound) by its lower bound.
  out << "  histogram (µs):";
  const char* sep = " ";
  for (std::size_t i = 0; i < TurnaroundStats::kBuckets; ++i) {
    if (s.buckets()[i] == 0) continue;
    out << sep
        << (i + 1 == TurnaroundStats::kBuckets ? ">= " + us(TurnaroundStats::bucket_upper_ns(i - 1))
                                               : "< " + us(TurnaroundStats::bucket_upper_ns(i)))
        << ": " << s.buckets()[i];
    sep = ", ";
  }
  out << std::endl;
}

}  // namespace rs4sim::app
