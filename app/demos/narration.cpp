#include "app/demos/narration.h"

#include "app/runtime/run_session.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <thread>

namespace rs4sim::app {

Narration::Narration(std::ostream& out, const dp::Clock& clock, RunUntil run_until, Stamp stamp)
    : out_(out), clock_(clock), run_until_(std::move(run_until)), stamp_(stamp), t0_(clock.now()) {}

std::string Narration::stamp() const {
  const dp::Duration since = clock_.now() - t0_;
  char t[32];
  if (stamp_ == Stamp::kMilliseconds) {
    const auto us = std::chrono::duration_cast<std::chrono::microseconds>(since).count();
    std::snprintf(t, sizeof t, "%9.3f ms  ", static_cast<double>(us) / 1000.0);
  } else {
    std::snprintf(t, sizeof t, "[%8.3f s] ", std::chrono::duration<double>(since).count());
  }
  return t;
}

void Narration::say(const std::string& text) const { out_ << stamp() << text << '\n'; }

void Narration::run_for(dp::Duration d) const {
  (void)run_until_([] { return false; }, d);
}

void Narration::progress(const std::string& text, bool final) const {
  if (live_) {
    out_ << '\r' << stamp() << text << (final ? "\n" : "") << std::flush;
  } else if (final) {
    say(text);
  }
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

RunUntil paced_to_wall_clock(RunUntil run, const dp::Clock& clock, WaitUntil wait) {
  if (!wait)
    wait = [](std::chrono::steady_clock::time_point t) { std::this_thread::sleep_until(t); };
  struct Anchor {
    std::optional<std::chrono::steady_clock::time_point> wall;
    dp::TimePoint sim{};
  };
  auto anchor = std::make_shared<Anchor>();
  return [run = std::move(run), &clock, anchor, wait = std::move(wait)](
             const std::function<bool()>& done, dp::Duration limit) {
    if (!anchor->wall) {
      anchor->wall = std::chrono::steady_clock::now();
      anchor->sim = clock.now();
    }
    const auto end = clock.now() + limit;
    while (true) {
      const auto slice = std::min<dp::Duration>(std::chrono::milliseconds(10), end - clock.now());
      const bool ok = run(done, slice);
      wait(*anchor->wall + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                               clock.now() - anchor->sim));
      if (ok) return true;
      if (clock.now() >= end) return done();
    }
  };
}

RunUntil in_session(RunUntil run, const dp::Clock& clock, bool realtime, RunSession& session) {
  if (realtime) {
    return paced_to_wall_clock(std::move(run), clock,
                               [&session](std::chrono::steady_clock::time_point t) {
                                 if (!session.run_until(t)) throw DemoInterrupted{};
                               });
  }
  return [run = std::move(run), &session](const std::function<bool()>& done,
                                          dp::Duration limit) {
    const bool ok = run(done, limit);
    if (!session.poll()) throw DemoInterrupted{};
    return ok;
  };
}

bool run_steps(const std::vector<std::function<bool()>>& steps) {
  return std::all_of(steps.begin(), steps.end(), [](const auto& step) { return step(); });
}

int run_story(const Narration& n, const std::vector<std::function<bool()>>& steps) {
  try {
    const bool ok = run_steps(steps);
    n.print(ok ? "\ndemo: all steps passed\n" : "\ndemo: FAILED\n");
    return ok ? 0 : 1;
  } catch (const DemoInterrupted&) {
    n.print("\ndemo interrupted\n");
    return kInterruptedExit;
  }
}

}  // namespace rs4sim::app
