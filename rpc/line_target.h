#pragma once
// The line of an RS-485 device's run on the simulated clock (`rs4sim run --device
// gridscan|metron|polaris --link memory --grpc`, docs/rpc.md "Exchange"): the device (its tap)
// on a stream::MemoryLine driven by the manual clock, and what a harness does on it through
// the API:
//   * exchange(): the harness's request goes on the line at now (after its wire time it has
//     arrived), the clock runs until the device's reply has arrived whole or `timeout` of
//     simulated time has passed; the reply is the first frame the device began to send after
//     the request had arrived. Both frames take their wire time at the device's line rate
//     (stream::character_time: 10 or 11 bit times per character per its LineSettings);
//   * receive(): the frames nobody asked for (the GridScan's power-up messages and its
//     streaming, a METRON's periodic reports), oldest first, as they arrived;
//   * SimulatedLineTarget: SimTime for such a run (Now, Advance), the event hub polled after
//     every step.
// Everything runs on the loop thread (through the Executor), as every core call does.

#include "rpc/event_hub.h"
#include "rpc/run_target.h"
#include "stream/memory_line.h"

#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rs4sim::rpc {

class SimulatedLine {
 public:
  // The frames kept for receive(); older ones are dropped (and counted) beyond.
  static constexpr std::size_t kMaxUnsolicited = 4096;

  SimulatedLine(stream::ManualClock& clock, stream::ByteDevice& device);
  SimulatedLine(const SimulatedLine&) = delete;
  SimulatedLine& operator=(const SimulatedLine&) = delete;

  // The link's start: the device's first on_time() at now (GridScan: its power-up message).
  void start() { line_.start(); }

  struct Exchanged {
    stream::TimePoint sent{};                // the request's first bit left the harness
    stream::TimePoint arrived{};             // its last bit reached the device
    std::optional<stream::LineFrame> reply;  // nullopt: none within the timeout
  };
  Exchanged exchange(std::span<const std::uint8_t> request, stream::Duration timeout);
  // The unsolicited frames that have arrived, oldest first (and forgets them).
  std::vector<stream::LineFrame> receive();
  [[nodiscard]] std::uint64_t unsolicited_dropped() const noexcept { return dropped_; }

  // Runs the line until `done` holds after a step or `limit` passed; returns done().
  bool run_until(const std::function<bool()>& done, stream::Duration limit);
  [[nodiscard]] stream::TimePoint now() const { return clock_.now(); }
  [[nodiscard]] stream::LineSettings line_settings() const { return device_.line_settings(); }
  [[nodiscard]] stream::MemoryLine& line() noexcept { return line_; }
  [[nodiscard]] const stream::ByteCounters& counters() const { return line_.counters(); }

 private:
  void on_frame(const stream::LineFrame& frame);

  stream::ManualClock& clock_;
  stream::ByteDevice& device_;
  stream::MemoryLine line_;
  std::deque<stream::LineFrame> unsolicited_;
  std::uint64_t dropped_ = 0;
  std::optional<stream::TimePoint> awaiting_;  // an exchange's request arrived then
  std::optional<stream::LineFrame> reply_;
};

// The RunTarget of a simulated RS-485 run: no RS4, the manual clock moved by SimTime, the hub
// watching the device and polled after every call that moves the time.
class SimulatedLineTarget final : public RunTarget {
 public:
  SimulatedLineTarget(stream::DeviceKind kind, std::unique_ptr<Watcher> watcher,
                      SimulatedLine& line);
  [[nodiscard]] std::vector<std::uint8_t> addresses() const override { return {address_}; }
  [[nodiscard]] dp::TimePoint now() const override { return line_.now(); }
  [[nodiscard]] bool simulated() const override { return true; }
  bool run_until(const std::function<bool()>& done, dp::Duration limit) override;
  void after(dp::Duration delay, std::function<void()> f) override;
  dp::link::MemoryBus* bus() override { return nullptr; }
  EventHub* events() override { return hub_.get(); }
  [[nodiscard]] stream::DeviceKind kind() const override { return kind_; }

 private:
  stream::DeviceKind kind_;
  std::uint8_t address_;
  SimulatedLine& line_;
  std::shared_ptr<EventHub> hub_ = std::make_shared<EventHub>();
};

}  // namespace rs4sim::rpc
