#include "rpc/line_target.h"

#include <utility>

namespace rs4sim::rpc {

SimulatedLine::SimulatedLine(stream::ManualClock& clock, stream::ByteDevice& device)
    : clock_(clock), device_(device), line_(clock, device) {
  line_.set_peer([this](const stream::LineFrame& f) { on_frame(f); });
}

void SimulatedLine::on_frame(const stream::LineFrame& frame) {
  if (awaiting_ && !reply_ && frame.start >= *awaiting_) {
    reply_ = frame;
    return;
  }
  if (unsolicited_.size() == kMaxUnsolicited) {
    unsolicited_.pop_front();
    ++dropped_;
  }
  unsolicited_.push_back(frame);
}

SimulatedLine::Exchanged SimulatedLine::exchange(std::span<const std::uint8_t> request,
                                                 stream::Duration timeout) {
  Exchanged out;
  // The harness's transmitter may still be busy with an earlier write (none by exchange()).
  out.sent = std::max(clock_.now(), line_.peer_free());
  line_.write(request);
  out.arrived = line_.peer_free();
  awaiting_ = out.arrived;
  reply_.reset();
  line_.run_until(out.sent + timeout, [this] { return reply_.has_value(); });
  out.reply = std::exchange(reply_, std::nullopt);
  awaiting_.reset();
  return out;
}

std::vector<stream::LineFrame> SimulatedLine::receive() {
  std::vector<stream::LineFrame> out(std::make_move_iterator(unsolicited_.begin()),
                                     std::make_move_iterator(unsolicited_.end()));
  unsolicited_.clear();
  return out;
}

bool SimulatedLine::run_until(const std::function<bool()>& done, stream::Duration limit) {
  return line_.run_until(clock_.now() + limit, done);
}

SimulatedLineTarget::SimulatedLineTarget(stream::DeviceKind kind, std::unique_ptr<Watcher> watcher,
                                         SimulatedLine& line)
    : kind_(kind), address_(watcher->address()), line_(line) {
  hub_->watch(std::move(watcher));
}

bool SimulatedLineTarget::run_until(const std::function<bool()>& done, dp::Duration limit) {
  const bool reached = line_.run_until(
      [&] {
        hub_->poll(line_.now());
        return done();
      },
      limit);
  hub_->poll(line_.now());
  return reached;
}

void SimulatedLineTarget::after(dp::Duration delay, std::function<void()> f) {
  (void)line_.run_until([] { return false; }, delay);
  f();
  hub_->poll(line_.now());
}

}  // namespace rs4sim::rpc
