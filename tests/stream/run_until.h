#pragma once
// Real-time tests: runs an io_context until `done()` or `timeout`; returns done(). Every wait
// is bounded and ends as soon as the condition holds; no fixed sleep decides a result.

#include "stream/clock.h"

#include <boost/asio/io_context.hpp>

#include <chrono>
#include <functional>

namespace rs4sim::stream::testing {

inline bool run_until(boost::asio::io_context& io, const std::function<bool()>& done,
                      Duration timeout = std::chrono::seconds(10)) {
  const auto end = SteadyClock::now() + timeout;
  while (!done() && SteadyClock::now() < end) {
    io.run_for(std::chrono::milliseconds(5));
    if (io.stopped()) io.restart();
  }
  return done();
}

}  // namespace rs4sim::stream::testing
