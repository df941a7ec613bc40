// Rs232Port: the PC adapter, the line, the 0x23 stream and the transmit queue ([docs/rs232.md]).
#include "rs4/rs232/rs232_port.h"

#include "rs4/adapter/rs4_commands.h"
#include "stream/transmit_queue.h"

#include <algorithm>

namespace rs4sim::rs4::rs232 {
namespace {

bool scanning(const scanner::Scanner& rs4) {
  const auto st = rs4.status();
  return (st.state == scanner::ScannerState::kMeasuring ||
          st.state == scanner::ScannerState::kError) &&
         st.scan_counter != 0;
}

}  // namespace

Rs232Port::Rs232Port(adapter::Adapter& adapter, const PortOptions& options)
    : adapter_(adapter),
      options_(options),
      line_(line_8n1(options.baud)),
      deframer_(options.max_body) {
  adapter_.set_rs4_event_listener([this](const scanner::Rs4Event& e) { on_rs4_event(e); });
}

Rs232Port::~Rs232Port() { adapter_.set_rs4_event_listener({}); }

void Rs232Port::attach(stream::TimePoint now) {
  attached_ = true;
  adapter_.attach_pc_adapter(now);  // [RS4 manual §5.1.1] bit 3
  sync_adapter(now);
  wake();
}

void Rs232Port::detach(stream::TimePoint now) {
  attached_ = false;
  adapter_.detach_pc_adapter(now);  // [RS4 manual §7.1, §7.2]: removal sets Proxy-Request
  sync_adapter(now);
  wake();
}

bool Rs232Port::reachable() const noexcept {
  return attached_ && adapter_.rs232_switched_through() &&
         adapter_.scanner().status().state != scanner::ScannerState::kOff;
}

// Runs the adapter (and its scanner) up to `now`, then opens or closes the session.
void Rs232Port::sync_adapter(stream::TimePoint now) {
  now_ = now;
  adapter_.on_time(now);
  const bool reach = reachable();
  if (reach == open_) return;
  if (!reach) {
    close_session(now);
    return;
  }
  open_ = true;
  deframer_ = protocol::Rs232Deframer(options_.max_body);
  session_.start(adapter_.scanner(), now);  // the RS232 path may write the set (docs/rs232.md)
  streaming_ = options_.stream_on_attach;
  streamed_scan_.reset();
  if (scanning(adapter_.scanner())) streamed_scan_ = adapter_.scanner().last_scan().scan_number;
}

// DECISION (docs/rs232.md): removing the PC adapter ends the session: queued frames are
// dropped, the stream stops and the line returns to its configured rate; an open download is
// discarded and the RS4 leaves its configuration mode with its set unchanged.
void Rs232Port::close_session(stream::TimePoint now) {
  open_ = false;
  session_.stop(adapter_.scanner(), now);
  adapter_.on_time(now);  // the adapter sees the RS4 leave configuration
  streaming_ = false;
  transmit_.clear();
  pending_line_.reset();
  line_ = line_8n1(options_.baud);
}

void Rs232Port::on_bytes(std::span<const std::uint8_t> bytes, stream::TimePoint now) {
  in_call_ = true;
  sync_adapter(now);
  if (!open_) {
    counters_.ignored_while_detached += bytes.size();
  } else {
    events_.clear();
    deframer_.feed(bytes, events_);
    for (const auto& event : events_) {
      if (event) {
        interpret(event.value(), now);
      } else {
        ++counters_.framing_errors;  // DECISION: a frame that cannot be trusted gets silence
      }
    }
  }
  in_call_ = false;
}

void Rs232Port::on_time(stream::TimePoint now) {
  if (pending_line_ && now >= pending_line_at_) {
    line_ = *pending_line_;  // the acknowledgement has left at the old rate
    pending_line_.reset();
    ++counters_.baud_changes;
  }
  in_call_ = true;
  sync_adapter(now);
  if (open_ && streaming_) stream_scan(now);
  in_call_ = false;
}

std::optional<stream::TimePoint> Rs232Port::next_deadline() const {
  std::optional<stream::TimePoint> next;
  const auto consider = [&next](stream::TimePoint t) {
    if (t != stream::TimePoint::max() && (!next || t < *next)) next = t;
  };
  if (pending_line_) consider(pending_line_at_);
  if (open_ && streaming_) consider(adapter_.scanner().next_deadline());
  if (attached_ && !open_) {  // waiting for the switch-through (boot, a running sync)
    if (const auto t = adapter_.next_deadline()) consider(*t);
  }
  return next;
}

std::optional<std::vector<std::uint8_t>> Rs232Port::take_transmit() {
  return stream::take_front(transmit_);
}

// The newest scan, once; skipped while the previous frames still occupy the line (a full
// 529-value contour takes ≈188 ms at 57 600 baud, longer than the 40 ms scan period).
void Rs232Port::stream_scan(stream::TimePoint now) {
  const auto& rs4 = adapter_.scanner();
  if (!scanning(rs4)) return;
  const std::uint32_t scan = rs4.last_scan().scan_number;
  if (streamed_scan_ == scan) return;
  streamed_scan_ = scan;
  if (now < line_busy_until_) {
    ++counters_.scans_skipped_busy;
    return;
  }
  ++counters_.measurements;
  send(adapter::measurement_telegram(rs4), now);
}

void Rs232Port::send(std::vector<std::uint8_t> body, stream::TimePoint now) {
  auto frame = protocol::frame_rs232(body);
  if (!frame) return;  // not reached: bodies come from the encoders (CMD ∉ {00, FF})
  const auto start = std::max(now, line_busy_until_);
  line_busy_until_ =
      start + stream::character_time(line_, static_cast<double>(frame.value().size()));
  transmit_.push_back(std::move(frame.value()));
}

// 0x53/0x54 as the RS4 emits them ([RS4 manual §5.2.3.2, §5.2.3.3]), also when the PROFIBUS
// side's loop collected them (then the link learns of it through wake()).
void Rs232Port::on_rs4_event(const scanner::Rs4Event& e) {
  if (!open_) return;
  ++counters_.events;
  send(adapter::event_telegram(adapter_.scanner(), e), std::max(e.at, now_));
  if (!in_call_) wake();  // collected by the PROFIBUS side's loop: tell the link
}

}  // namespace rs4sim::rs4::rs232
