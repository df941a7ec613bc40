#include "app/narration.h"

#include <algorithm>
#include <cstdio>

namespace rs4sim::app {

Narration::Narration(std::ostream& out, const dp::Clock& clock, RunUntil run_until, Stamp stamp)
    : out_(out), clock_(clock), run_until_(std::move(run_until)), stamp_(stamp), t0_(clock.now()) {}

void Narration::say(const std::string& text) const {
  const dp::Duration since = clock_.now() - t0_;
  char t[32];
  if (stamp_ == Stamp::kMilliseconds) {
    const auto us = std::chrono::duration_cast<std::chrono::microseconds>(since).count();
    std::snprintf(t, sizeof t, "%9.3f ms  ", static_cast<double>(us) / 1000.0);
  } else {
    std::snprintf(t, sizeof t, "[%8.3f s] ", std::chrono::duration<double>(since).count());
  }
  out_ << t << text << '\n';
}

void Narration::print(const std::string& text) const { out_ << text; }

bool Narration::check(bool ok, const std::string& what) const {
  if (!ok) out_ << "FAILED: " << what << "\n";
  return ok;
}

bool Narration::wait(const std::function<bool()>& done, dp::Duration limit,
                     const std::string& text) const {
  if (run_until_(done, limit)) {
    say(text);
    return true;
  }
  say("FAILED: " + text + " did not happen within " +
      std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(limit).count()) + " ms");
  return false;
}

long long Narration::ms_since(dp::TimePoint since) const {
  return std::chrono::duration_cast<std::chrono::milliseconds>(clock_.now() - since).count();
}

bool run_steps(const std::vector<std::function<bool()>>& steps) {
  return std::all_of(steps.begin(), steps.end(), [](const auto& step) { return step(); });
}

}  // namespace rs4sim::app
