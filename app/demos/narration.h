#pragma once
// The narrated-demo framework of the runtime: every `rs4sim demo` scenario (one per
// device entry) tells its story through a Narration and runs as a list of steps on the
// simulated bus (manual clock): each step waits for what the manual or the spec
// prescribes and fails the demo if it does not happen.

#include "dp/time/clock.h"

#include <chrono>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace rs4sim::app {

// Runs simulated time until `done` holds or `limit` passes; returns done().
using RunUntil = std::function<bool(const std::function<bool()>& done, dp::Duration limit)>;

class Narration {
 public:
  // How a line is stamped with the simulated time since the start.
  enum class Stamp : std::uint8_t {
    kMilliseconds,  // "   12.345 ms  text"
    kSeconds,       // "[  12.345 s] text"
  };

  Narration(std::ostream& out, const dp::Clock& clock, RunUntil run_until, Stamp stamp);

  // A time-stamped line.
  void say(const std::string& text) const;
  // An unstamped line (a heading, a blank line …), as given.
  void print(const std::string& text) const;
  // `ok`, or an unstamped "FAILED: what" line.
  bool check(bool ok, const std::string& what) const;
  // Runs until `done` (≤ limit); says `text` when it happened, the failure otherwise.
  bool wait(const std::function<bool()>& done, dp::Duration limit, const std::string& text) const;
  // Runs simulated time for `d` (through the same RunUntil as every wait).
  void run_for(dp::Duration d) const;
  // A progress line: on a terminal (`live`) it is redrawn in place on every call and ends
  // with `final`; elsewhere (a log, a pipe) only the final state is printed.
  void progress(const std::string& text, bool final) const;
  void set_live(bool live) { live_ = live; }
  // The simulated time since `since`, in whole milliseconds (for "after N ms").
  [[nodiscard]] long long ms_since(dp::TimePoint since) const;

  [[nodiscard]] std::ostream& out() const { return out_; }

 private:
  std::ostream& out_;
  const dp::Clock& clock_;
  RunUntil run_until_;
  [[nodiscard]] std::string stamp() const;

  Stamp stamp_;
  dp::TimePoint t0_;
  bool live_ = false;
};

// Waits until a wall-clock instant (default: sleeps; `demo --grpc`: runs the API's loop).
using WaitUntil = std::function<void(std::chrono::steady_clock::time_point)>;

// `run` paced to the wall clock (`rs4sim demo --realtime`): simulated time moves in slices
// of at most 10 ms and the wall clock waits for it (through `wait`), so every duration of the
// story takes as long as on the device.
RunUntil paced_to_wall_clock(RunUntil run, const dp::Clock& clock, WaitUntil wait = {});

class RunSession;

// Thrown from a demo's wait once SIGINT/SIGTERM asked its RunSession to stop; the demo
// prints "demo interrupted" and exits 130 (128 + SIGINT, as a shell reports it).
struct DemoInterrupted {};
constexpr int kInterruptedExit = 130;

// `run` inside the demo's session: paced to the wall clock with `realtime` (the session's
// loop runs in the waits: gRPC calls, signals), else as fast as it goes with the loop polled
// after every run. Throws DemoInterrupted once the session is stopping.
RunUntil in_session(RunUntil run, const dp::Clock& clock, bool realtime, RunSession& session);

// Runs the steps in order until one fails; returns true when all passed.
bool run_steps(const std::vector<std::function<bool()>>& steps);

// A demo's whole story: the steps in order until one fails, then "demo: all steps passed" or
// "demo: FAILED" (exit 0 / 1), or "demo interrupted" (exit 130) on DemoInterrupted.
int run_story(const Narration& n, const std::vector<std::function<bool()>>& steps);

}  // namespace rs4sim::app
