// RunSession (app/runtime/run_session.h): the signals, the ordered stop, --duration.
#include "app/runtime/run_session.h"

#include <gtest/gtest.h>

#include <csignal>
#include <boost/asio/post.hpp>

#include <sstream>
#include <string>
#include <thread>

namespace rs4sim::app {
namespace {

using Reason = RunSession::StopReason;

// A SIGTERM that arrives while the process is still starting (main() has blocked it, no
// handler is installed yet) is not lost and does not kill the process: the session's loop
// sees it as soon as it runs and stops in order.
TEST(RunSession, SignalBeforeTheSessionExistsStopsItCleanly) {
  block_stop_signals();
  ASSERT_EQ(raise(SIGTERM), 0);  // pending: blocked in this thread
  std::ostringstream out;
  RunSession session(out);
  std::string order;
  session.on_stop([&] { order += "runner;"; });
  EXPECT_EQ(session.run(), Reason::kSignal);
  EXPECT_EQ(order, "runner;");
}

TEST(RunSession, SigintStopsLikeSigterm) {
  block_stop_signals();
  ASSERT_EQ(raise(SIGINT), 0);
  std::ostringstream out;
  RunSession session(out);
  EXPECT_EQ(session.run(), Reason::kSignal);
}

TEST(RunSession, StopStepsRunOnceInTheirOrderBeginStepsFirst) {
  std::ostringstream out;
  RunSession session(out);
  std::string order;
  session.on_stop([&] { order += "b;"; });
  session.on_stop_begin([&] { order += "a;"; });
  session.on_stop([&] { order += "c;"; });
  boost::asio::post(session.io(), [&] {
    session.request_stop();
    session.request_stop(Reason::kSignal);  // the first reason stays; nothing runs twice
  });
  EXPECT_EQ(session.run(), Reason::kRequested);
  EXPECT_EQ(order, "a;b;c;");
  session.finish();  // after the stop: nothing more happens
  EXPECT_EQ(order, "a;b;c;");
}

// A simulation run in slices (run_simulated, the demos' waits) polls the loop and sees the
// stop between two slices.
TEST(RunSession, PollTellsASimulationToStop) {
  std::ostringstream out;
  RunSession session(out);
  EXPECT_TRUE(session.poll());
  boost::asio::post(session.io(), [&] { session.request_stop(); });
  EXPECT_FALSE(session.poll());
  EXPECT_TRUE(session.stopping());
  session.finish();
}

TEST(RunSession, WorkPostedFromAnotherThreadRunsOnTheLoop) {
  std::ostringstream out;
  RunSession session(out);
  int ran = 0;
  std::thread client([&] {
    session.executor().run([&] { ++ran; });  // waits until the loop ran it
    boost::asio::post(session.io(), [&] { session.request_stop(); });
  });
  session.run();
  client.join();
  EXPECT_EQ(ran, 1);
}

}  // namespace
}  // namespace rs4sim::app
