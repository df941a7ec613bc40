// RunSession's --duration on a real-time link: a wall-clock timer on the loop (realtime tier;
// app/runtime/run_session.h).
#include "app/runtime/run_session.h"

#include <gtest/gtest.h>

#include <chrono>
#include <sstream>

namespace rs4sim::app {
namespace {

using Reason = RunSession::StopReason;

TEST(RunSession, DurationEndsTheRun) {
  std::ostringstream out;
  RunSession session(out);
  bool stopped = false;
  session.on_stop([&] { stopped = true; });
  const auto start = std::chrono::steady_clock::now();
  session.stop_after(0.02);
  EXPECT_EQ(session.run(), Reason::kDuration);
  EXPECT_TRUE(stopped);
  // Not before the 20 ms (the upper side is the machine's, not asserted).
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(20));
}

}  // namespace
}  // namespace rs4sim::app
