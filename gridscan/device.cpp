// Power, timing, framing and transmission of the GridScan device; the commands are in
// device_commands.cpp.
#include "gridscan/device.h"

#include "stream/transmit_queue.h"

#include <algorithm>
#include <utility>

namespace rs4sim::gridscan {

using stream::TimePoint;

Device::Device(const Options& options)
    : options_(options),
      configuration_(options.configuration),
      framer_(options.idle_gap(), kMaxFrame),
      cycle_(options.cycle_time()) {
  scene_.door_position = options.door_position.value_or(options.elements);
  scene_.blocked = options.blocked & element_mask(options.elements);
  scene_.soiling = options.soiling;
  scene_.alignment_value = options.alignment_value;
  alignment_armed_ = options.alignment_armed;
}

void Device::start_if_waiting(TimePoint now) {
  if (!waiting_for_start_) return;
  waiting_for_start_ = false;
  power_up(now);
}

void Device::power_on(TimePoint now) {
  waiting_for_start_ = false;
  if (power_ == PowerState::kOff) power_up(now);
  wake();
}

void Device::power_off() {
  waiting_for_start_ = false;
  power_ = PowerState::kOff;
  framer_.reset();
  transmit_.clear();
  pending_.reset();
  wake();
}

// [GridScan manual §10.1.1] "Power-up sequence": Info: Get version as soon as the
// communication is up; SeqCnt 0 and 1 for the two power-up messages (DECISION: the only
// start that reproduces the exchange of [GridScan manual §10.3], docs/gridscan.md).
void Device::power_up(TimePoint now) {
  power_ = PowerState::kStarting;
  power_up_at_ = now;
  ready_at_ = now + options_.ready_time;
  cycle_ = options_.cycle_time();  // t_CYCLE of this power-up (set_cycle: the next one's)
  framer_.reset();
  pending_.reset();
  mode_ = CommMode::kPolling;
  change_allowed_ = config_read_ = test_pending_ = alignment_active_ = false;
  stream_seq_ = 0;
  last_seq_ = 0;
  last_sent_.reset();
  send(response_id(CommandId::kInfoGetVersion), 0,
       encode_version(options_.sw_version, options_.hw_version).value());
}

void Device::become_ready(TimePoint t) {
  power_ = PowerState::kReady;
  last_seq_ = 1;
  send(response_id(CommandId::kDataReducedState), last_seq_,
       encode_reduced_state(scanned_report()));
  // [GridScan manual §10.1.3]: alignment values on an interrupted power-up when armed.
  alignment_active_ = alignment_armed_ && scanned_report().interrupted;
  mode_ = options_.power_up_mode;
  if (mode_ == CommMode::kStandBy) standby_door_ = scene_.door_position;
  if (periodic()) next_end_ = t + cycle_;
}

std::string Device::set_cycle(stream::Duration cycle) {
  if (auto why = check_cycle(options_.elements, cycle); !why.empty()) return why;
  Options next = options_;
  next.cycle = cycle;
  if (auto why = next.validate(); !why.empty()) return why;
  options_.cycle = cycle;
  return {};
}

void Device::on_time(TimePoint now) {
  start_if_waiting(now);
  advance(now);
}

void Device::on_bytes(std::span<const std::uint8_t> bytes, TimePoint now) {
  start_if_waiting(now);
  advance(now);
  if (power_ == PowerState::kOff) return;
  framer_.feed(bytes, now);
  while (auto f = framer_.poll(now)) receive(*f);
}

// Runs every event due at or before `now` in time order: ready, frame ends, cycle ends.
void Device::advance(TimePoint now) {
  for (;;) {
    std::optional<TimePoint> ready;
    if (power_ == PowerState::kStarting) ready = ready_at_;
    const auto frame = framer_.deadline();
    const auto cycle = tick_deadline();
    const TimePoint t =
        std::min({ready.value_or(TimePoint::max()), frame.value_or(TimePoint::max()),
                  cycle.value_or(TimePoint::max())});
    if (t > now) return;
    if (ready && *ready == t) {
      become_ready(t);
    } else if (frame && *frame == t) {
      while (auto f = framer_.poll(t)) receive(*f);
    } else {
      tick(next_end_, now);
    }
  }
}

std::optional<TimePoint> Device::next_deadline() const {
  if (waiting_for_start_ || power_ == PowerState::kOff) return std::nullopt;
  std::optional<TimePoint> d = framer_.deadline();
  const auto earliest = [&d](TimePoint t) { d = d ? std::min(*d, t) : t; };
  if (power_ == PowerState::kStarting) earliest(ready_at_);
  if (const auto c = tick_deadline()) earliest(*c);
  return d;
}

std::optional<std::vector<std::uint8_t>> Device::take_transmit() {
  return stream::take_front(transmit_);
}

// A frame cut by idle gap. Requests are exactly 10 bytes ([GridScan manual §9.2.4] "All
// request packages have no payload"); anything else is dropped and counted.
void Device::receive(const stream::GapFrame& f) {
  ++counters_.frames;
  if (f.oversized || f.bytes.size() > kMinFrame) {
    ++counters_.oversized;
    return;
  }
  auto raw = inspect(f.bytes);
  if (!raw) {
    ++counters_.truncated;
    return;
  }
  if (power_ != PowerState::kReady) {
    ++counters_.not_ready;
    return;
  }
  // [GridScan manual §11]: one request per t_CYCLE (DECISION: a second one is dropped).
  if (pending_) {
    ++counters_.busy;
    return;
  }
  const TimePoint completed = f.last_byte + framer_.gap();
  const bool idle = !periodic();
  pending_ = Pending{std::move(raw).value(), cycle_end_after(completed)};
  if (idle) next_end_ = pending_->cycle_end;
}

bool Device::periodic() const {
  return power_ == PowerState::kReady &&
         (mode_ == CommMode::kFullStreaming || mode_ == CommMode::kReducedStreaming ||
          alignment_active_);
}

std::optional<TimePoint> Device::tick_deadline() const {
  if (power_ != PowerState::kReady || (!pending_ && !periodic())) return std::nullopt;
  return faults_.transmit.delay(next_end_);
}

TimePoint Device::cycle_end_after(TimePoint t) const {
  const auto period = cycle_;
  const auto since = std::max(t - ready_at_, stream::Duration::zero());
  return ready_at_ + (since / period + 1) * period;
}

// [GridScan manual §11]: after the cycle, the answer to the request received in it, then
// the streaming message.
void Device::tick(TimePoint cycle_end, TimePoint now) {
  if (pending_ && pending_->cycle_end <= cycle_end) {
    const RawFrame request = std::move(pending_->request);
    pending_.reset();
    answer_request(request, cycle_end);
    if (power_ != PowerState::kReady) return;  // restarted by a configuration change
  }
  send_cycle_messages();
  const TimePoint from = std::max(cycle_end, now - faults_.transmit.late);
  next_end_ =
      pending_ ? std::min(pending_->cycle_end, cycle_end_after(from)) : cycle_end_after(from);
}

void Device::send_cycle_messages() {
  if (mode_ == CommMode::kFullStreaming || mode_ == CommMode::kReducedStreaming) {
    const bool full = mode_ == CommMode::kFullStreaming;
    const auto id = response_id(full ? CommandId::kDataFullState : CommandId::kDataReducedState);
    send(id, stream_seq_++, state_payload(full));
    ++counters_.streamed;
  }
  if (!alignment_active_) return;
  // [GridScan manual §10.1.3]: the first time the curtain is free it leaves alignment
  // mode for good; until then an alignment value every cycle (DECISION: 0xA4 on the
  // streaming SeqCnt).
  if (!scanned_report().interrupted) {
    alignment_active_ = alignment_armed_ = false;
    return;
  }
  send(response_id(CommandId::kInfoGetAlignmentValue), stream_seq_++,
       encode_u16_le(scene_.alignment_value));
  ++counters_.streamed;
}

// The frame as it goes on the wire, with the transmission faults of
// [GridScan manual §10.2.2] applied (faults.h).
void Device::send(std::uint8_t id, std::uint8_t seq, const Payload& payload) {
  if (faults_.transmit.silent) return;  // nothing on the wire, nothing to insert again later
  Frame f{seq, id, payload};
  std::optional<Frame> previous;
  if (faults_.insert_frames) previous = std::move(last_sent_);
  last_sent_ = f;  // assigned in place: the payload's storage is reused, frame after frame
  if (faults_.wrong_seq) ++f.seq;
  if (faults_.direction_bit) f.id &= kIdMask;
  const auto seal = [this](const Frame& frame) {
    auto bytes = encode(frame);
    if (faults_.bad_crc) bytes[bytes.size() - kCrcSize] ^= 0x01U;
    return bytes;
  };
  if (faults_.insert_frames && previous) {
    previous->seq = f.seq;
    transmit_.push_back(seal(*previous));
  }
  auto bytes = seal(f);
  if (faults_.repeat_frames) transmit_.push_back(bytes);
  transmit_.push_back(std::move(bytes));
}

// Response SeqCnt = request SeqCnt + 1, and the next request must carry one more
// ([GridScan manual §9.2.2]).
void Device::send_answer(CommandId c, std::uint8_t request_seq, const Payload& payload) {
  last_seq_ = static_cast<std::uint8_t>(request_seq + 1U);
  send(response_id(c), last_seq_, payload);
  ++counters_.answered;
}

Leds Device::leds(TimePoint now) const {
  LedInputs in;
  in.powered = power_ != PowerState::kOff;
  in.starting = power_ == PowerState::kStarting;
  in.internal_failure = scene_.internal_failure;
  in.static_blink =
      configuration_ == Configuration::kStatic && now - power_up_at_ <= options_.config_window;
  in.interrupted = current_report().interrupted;
  return leds_for(in);
}

StateReport Device::current_report() const {
  if (mode_ != CommMode::kStandBy) return scanned_report();
  Scene frozen = scene_;
  frozen.door_position = standby_door_;
  return all_interrupted_report(frozen, elements(), configuration_);
}

// What the elements report in a scan: an element stuck free reads free whatever is in
// front of it (the door's cover included).
StateReport Device::scanned_report() const {
  Scene seen = scene_;
  seen.blocked &= ~faults_.stuck_free;
  StateReport r = report_of(seen, elements(), configuration_);
  r.elements &= ~faults_.stuck_free;
  return r;
}

// The scan of a Test input ([GridScan manual §10.1.2]): every element shows interrupted,
// except one stuck free.
StateReport Device::test_report() const {
  StateReport r = all_interrupted_report(scene_, elements(), configuration_);
  r.elements &= ~faults_.stuck_free;
  r.interrupted = r.elements != 0;
  return r;
}

std::string_view to_token(PowerState p) noexcept {
  switch (p) {
    case PowerState::kOff: return "off";
    case PowerState::kStarting: return "starting";
    case PowerState::kReady: return "ready";
  }
  return "?";
}

}  // namespace rs4sim::gridscan
