#include "metron/device.h"

#include "metron/slave_reply.h"
#include "stream/transmit_queue.h"

#include <algorithm>

namespace rs4sim::metron {
namespace {

ReceiverConfig receiver_config(const Options& o) {
  // DECISION: the rest of an over-long message is the bytes that follow within 10
  // character times (5.7 ms at 19200 baud) of each other.
  return {o.node_enabled, o.wire.frame_start, o.checksum_reading, o.receive_timeout,
          stream::character_time(line_settings(o), 10.0)};
}

}  // namespace

Device::Device(Options options)
    : options_(std::move(options)),
      scene_(options_.beams),
      receiver_(receiver_config(options_)),
      standard_(options_) {
  (void)scene_.set_interrupted(options_.blocked);  // validate() has checked the beams
}

stream::LineSettings Device::line_settings() const { return metron::line_settings(options_); }

void Device::on_bytes(std::span<const std::uint8_t> bytes, stream::TimePoint now) {
  if (resetting(now)) {
    counters_.ignored_in_reset += bytes.size();
    return;
  }
  if (options_.line_mode == LineMode::kStandard) {
    standard_.on_bytes(bytes);
    return;
  }
  receiver_.feed(bytes, now);
  process_messages(now);
}

void Device::on_byte_with_parity_error(std::uint8_t byte, stream::TimePoint now) {
  if (resetting(now) || options_.line_mode == LineMode::kStandard) {
    on_bytes(std::span<const std::uint8_t>(&byte, 1), now);
    return;
  }
  receiver_.feed(std::span<const std::uint8_t>(&byte, 1), now);
  receiver_.mark_parity_error();
  process_messages(now);
}

void Device::on_time(stream::TimePoint now) {
  if (!started_) {
    started_ = true;
    if (options_.line_mode == LineMode::kStandard) standard_.start(now);
  }
  if (options_.line_mode == LineMode::kSlave) {
    process_messages(now);
  } else if (!resetting(now)) {
    scratch_.clear();
    standard_.advance(now, scene_, scratch_);
    for (auto& f : scratch_) queue(std::move(f));
  }
  release(now);
}

void Device::process_messages(stream::TimePoint now) {
  while (auto m = receiver_.poll(now)) {
    const auto r = handle(*m, options_, scene_, state_);
    count(r);
    react(*m, r, now);
  }
}

void Device::react(const SlaveMessage& m, const Reaction& r, stream::TimePoint now) {
  if (r.reset) {
    ++counters_.resets;
    reset_until_ = now + options_.reset_time;
    receiver_.reset();
    pending_.clear();
    return;
  }
  if (!r.reply_code) return;
  std::optional<std::uint8_t> node;
  if (options_.node_enabled)
    node = static_cast<std::uint8_t>(options_.node + (faults_.wrong_node ? 1 : 0));
  auto bytes =
      encode_reply(options_.wire, node, *r.reply_code, r.reply_data, options_.checksum_reading);
  const auto due = std::max(now, m.first_byte + reply_delay(m.wire_bytes, options_.t_response));
  queue({due, std::move(bytes)});
}

void Device::count(const Reaction& r) {
  switch (r.disposition) {
    case Disposition::kExecuted: ++counters_.executed; break;
    case Disposition::kErrorAnswer: break;
    case Disposition::kParityRejected: ++counters_.parity_rejected; break;
    case Disposition::kNotForUs: ++counters_.not_for_us; break;
    case Disposition::kBroadcastIgnored: ++counters_.broadcast_ignored; break;
  }
  if (r.error) ++counters_.errors[static_cast<std::size_t>(*r.error)];
}

void Device::queue(Outgoing frame) {
  auto& b = frame.bytes;
  if (faults_.bad_checksum) {
    // The checksum byte where the table's layout puts it (by default a slave reply's last
    // byte, a report's byte before End), if the frame has one.
    const auto at = options_.line_mode == LineMode::kStandard
                        ? report_checksum_offset(options_.wire,
                                                 {options_.format, options_.separator,
                                                  options_.checksum},
                                                 b.size())
                        : reply_checksum_offset(options_.wire, options_.node_enabled, b.size());
    if (at && *at < b.size()) b[*at] = static_cast<std::uint8_t>(~b[*at]);
  }
  if (faults_.truncate && !b.empty()) b.pop_back();
  if (!pending_.schedule(std::move(b), frame.at, faults_.transmit)) ++counters_.suppressed;
}

void Device::release(stream::TimePoint now) {
  while (auto frame = pending_.pop_due(now)) {
    transmit_.push_back(std::move(*frame));
    ++counters_.frames_sent;
  }
}

std::optional<stream::TimePoint> Device::next_deadline() const {
  if (!started_) return stream::TimePoint{};
  std::optional<stream::TimePoint> d;
  const auto take = [&](std::optional<stream::TimePoint> t) {
    if (t && (!d || *t < *d)) d = t;
  };
  take(pending_.next_due());
  take(receiver_.deadline());
  if (options_.line_mode == LineMode::kStandard) take(standard_.deadline());
  return d;
}

std::optional<std::vector<std::uint8_t>> Device::take_transmit() {
  return stream::take_front(transmit_);
}

std::error_code Device::set_interrupted(std::span<const std::uint16_t> beams) {
  if (auto e = scene_.set_interrupted(beams)) return e;
  scene_changed();
  return {};
}

void Device::set_beam(std::uint16_t beam, bool interrupted) {
  scene_.set_interrupted(beam, interrupted);
  scene_changed();
}

void Device::set_input(bool high) {
  scene_.set_input(high);
  standard_.on_input(high, scene_);
  scene_changed();
}

std::string Device::set_timing(stream::Duration scan_cycle, stream::Duration t_response) {
  Options next = options_;
  next.scan_cycle = scan_cycle;
  next.t_response = t_response;
  if (auto why = next.validate(); !why.empty()) return why;
  options_.scan_cycle = scan_cycle;  // standard_ reads options_ by reference
  options_.t_response = t_response;
  wake();
  return {};
}

void Device::set_synchronised(bool synchronised) {
  scene_.set_synchronised(synchronised);
  scene_changed();
}

void Device::scene_changed() {
  state_.track(scene_);
  standard_.on_scene(scene_);
}

bool Device::ossd_on() const { return metron::ossd_on(state_, scene_); }

Counters Device::counters() const {
  Counters c = counters_;
  const auto& r = receiver_.stats();
  c.messages = r.messages;
  c.noise_bytes = r.noise_bytes;
  c.truncated = r.truncated;
  c.too_long = r.too_long;
  c.resync_bytes = r.resync_bytes;
  const auto& s = standard_.stats();
  c.reports = s.reports;
  c.reports_dropped = s.dropped;
  c.report_requests = s.requests;
  c.other_bytes = s.other_bytes;
  return c;
}

}  // namespace rs4sim::metron
