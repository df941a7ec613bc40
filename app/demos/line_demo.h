#pragma once
// The rig of a byte device's narrated demo (GridScan, METRON, Polaris; app/demos/demos.h): the
// device alone on the simulated line (stream::MemoryLine, every frame with its wire time) on
// its own manual clock, the frames it sent, and the narration. With --realtime the steps are
// paced on the wall clock inside the run's session (in_session). A demo derives from it and
// tells its story with run_story.

#include "app/demos/narration.h"
#include "stream/memory_line.h"

#include <ostream>
#include <utility>
#include <vector>

namespace rs4sim::app {

template <class Device>
class LineDemo {
 public:
  template <class... DeviceArgs>
  LineDemo(std::ostream& out, bool realtime, RunSession& session, DeviceArgs&&... device_args)
      : device_(std::forward<DeviceArgs>(device_args)...),
        run_(in_session(
            [this](const std::function<bool()>& done, dp::Duration limit) {
              return line_.run_until(clock_.now() + limit, done);
            },
            clock_, realtime, session)),
        n_(out, clock_, run_, Narration::Stamp::kMilliseconds) {
    line_.set_peer([this](const stream::LineFrame& f) { arrived_.push_back(f); });
  }

 protected:
  stream::ManualClock clock_;
  Device device_;
  stream::MemoryLine line_{clock_, device_};
  std::vector<stream::LineFrame> arrived_;  // the device's frames, oldest first
  RunUntil run_;
  Narration n_;
};

// `rs4sim demo --device NAME` of a LineDemo (its device built from `device_args`): its story's
// exit code.
template <class Demo, class... DeviceArgs>
int run_line_demo(RunSession& session, std::ostream& out, const DemoOptions& options,
                  DeviceArgs&&... device_args) {
  Demo demo(out, options.realtime, session, std::forward<DeviceArgs>(device_args)...);
  return demo.run();
}

}  // namespace rs4sim::app
