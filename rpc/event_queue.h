#pragma once
// One event stream's bounded queue (docs/rpc.md "Event stream"): the loop thread pushes, the
// stream's gRPC thread pops. When the client reads too slowly the queue fills up; further
// events are counted instead of stored, and the stream sees one EventsDropped{count} where
// they were lost, so memory stays bounded by the capacity whatever the client does.

#include "rpc/stream_handoff.h"
#include "rs4sim/v1/rs4.pb.h"

#include <chrono>
#include <cstdint>
#include <vector>

namespace rs4sim::rpc {

class EventQueue : public StreamHandoff {
 public:
  static constexpr std::size_t kDefaultCapacity = 4096;
  static constexpr std::size_t kMinCapacity = 16;
  static constexpr std::size_t kMaxCapacity = 1U << 20U;

  // `addresses` empty = every station.
  EventQueue(std::size_t capacity, bool telegrams, std::vector<std::uint8_t> addresses);

  [[nodiscard]] bool telegrams() const noexcept { return telegrams_; }
  [[nodiscard]] bool watches(std::uint8_t address) const noexcept;

  // Loop thread: appends `e` (its sequence is set here) or counts it as dropped.
  void push(v1::Event e);
  // Stream thread: the events queued so far, waiting up to `timeout` for the first one;
  // empty on timeout or once closed and drained.
  std::vector<v1::Event> pop(std::chrono::milliseconds timeout);
  // close(): no more events will come (the run ends), pop() returns at once.
  [[nodiscard]] std::uint64_t dropped_total() const;

 private:
  void push_dropped_locked(std::int64_t now_ns);

  const std::size_t capacity_;
  const bool telegrams_;
  const std::vector<std::uint8_t> addresses_;
  std::vector<v1::Event> events_;
  std::uint64_t sequence_ = 0;
  std::uint64_t dropped_ = 0;        // since the last EventsDropped
  std::uint64_t dropped_total_ = 0;  // over the stream's life
};

}  // namespace rs4sim::rpc
