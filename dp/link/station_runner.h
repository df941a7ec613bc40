#pragma once
// Drives dp::Station cores over a real-time Transport from one asio::io_context thread
// ([docs/design.md#one-event-loop], the Station contract in dp/station.h):
//   received bytes → fdl::Decoder → on_telegram() of every station (the cores filter by
//   address) → next_transmit() drained → fdl::encode → Transport::send();
//   one steady_timer armed for the earliest next_deadline() → on_time().
// `now` always comes from the injected Clock (RealClock in production).
//
// Framing on a byte stream (serial, pty): the decoder cuts frames by SD/LE/FCS/ED and
// rescans after a bad frame (dp/fdl/decoder.h). Line idle ≥ TSYN marks a frame boundary on
// a real line ([IEC 61158-4-3 bus parameters, timing]); user-space only sees bytes in OS-sized
// chunks, so the runner treats a pause of `idle_gap` (default: the larger of TSYN and 30 ms) inside
// a partial frame as that idle and drops the partial frame (counted malformed, fdl kTruncated). On
// UDP each datagram must be exactly one telegram; anything left over is malformed.
//
// Turnaround (dp/link/turnaround.h): a reply a station hands over while the runner handles
// received bytes is timed from that read (the one that completed the request) to the return
// of Transport::send() (one write() per telegram on a serial line), per station. With a slot
// time (`RunnerOptions::slot_time`, `rs4sim run --tsl`) a reply that would only be written
// later than TSL after the request is not sent: the master has given up on it and is sending
// its retry, so it would collide on the line ([IEC 61158-4-3 bus parameters, timing]: TSL).
// It is counted as late; the station's FCB state is left as if it had been sent, so the
// retry gets the stored reply, as from a real slave whose reply was lost.

#include "dp/fdl/decoder.h"
#include "dp/link/counters.h"
#include "dp/link/turnaround.h"
#include "dp/station.h"
#include "stream/coalesced_wake.h"
#include "stream/deadline_timer.h"
#include "stream/frame_tap.h"
#include "stream/transport.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace rs4sim::dp::link {

// The tap sees every telegram the runner received (re-encoded from the decoded telegram, so
// only well-formed frames) and every telegram it sent, with the runner's `now` (e.g. a capture).
using stream::FrameDirection;
using stream::FrameTap;
using stream::Transport;

struct RunnerOptions {
  Duration idle_gap = std::chrono::milliseconds(30);
  // The master's slot time; nullopt: every reply is sent however late.
  std::optional<Duration> slot_time;
  // Time the replies (TurnaroundStats); false only for the benchmark's baseline.
  bool turnaround = true;
};

class StationRunner final : private fdl::DecoderSink {
 public:
  StationRunner(boost::asio::io_context& io, const Clock& clock, Transport& transport,
                RunnerOptions options = {});
  StationRunner(const StationRunner&) = delete;
  StationRunner& operator=(const StationRunner&) = delete;

  // Adds a station (before start()) and installs its wake handler: a station that changes
  // outside a runner call gets one drain + timer re-arm posted to the loop (coalesced).
  // The station must outlive the runner.
  void add(Station& station);
  void set_frame_tap(FrameTap tap) { tap_ = std::move(tap); }
  // Starts receiving and calls on_time() once on every station.
  void start();
  // Stops the timers and closes the transport.
  void stop();
  [[nodiscard]] const StationCounters& counters() const { return counters_; }
  [[nodiscard]] const fdl::DecoderStats& decoder_stats() const { return decoder_.stats(); }
  [[nodiscard]] std::error_code last_error() const { return last_error_; }
  // The turnaround of the station at `address` (nullptr: no such station on this runner).
  [[nodiscard]] const TurnaroundStats* turnaround(std::uint8_t address) const;
  [[nodiscard]] const RunnerOptions& options() const { return options_; }

 private:
  void on_telegram(const fdl::Telegram& t) override;
  void on_decode_error(std::error_code e) override;
  void on_bytes(std::span<const std::uint8_t> bytes);
  void on_transport_error(std::error_code e);
  void on_timer();
  // `request_end`: the read that completed the request(s) these replies answer (nullptr:
  // a drain after a timer or a wake, nothing to time).
  void drain_all(const TimePoint* request_end = nullptr);
  void send_reply(std::size_t station, const TimePoint& request_end);
  void arm_timer();
  void arm_idle_timer();

  const Clock& clock_;
  Transport& transport_;
  RunnerOptions options_;
  std::vector<Station*> stations_;
  std::vector<TurnaroundStats> turnaround_;  // one per station, sized in add()
  fdl::Decoder decoder_;
  stream::DeadlineTimer timer_;
  boost::asio::steady_timer idle_timer_;
  stream::CoalescedWake wake_;
  StationCounters counters_;
  std::error_code last_error_;
  std::vector<std::uint8_t> encode_buf_;
  fdl::Telegram tx_scratch_;  // for stations that hand out copies (Station::next_transmit)
  std::vector<std::uint8_t> tap_buf_;
  FrameTap tap_;
  TimePoint now_{};
  std::uint64_t idle_generation_ = 0;
  bool running_ = false;
  bool received_ = false;  // a telegram arrived in the bytes being handled
};

}  // namespace rs4sim::dp::link
