#include "dp/link/memory_bus.h"

#include "dp/fdl/telegram_copy.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace rs4sim::dp::link {

static_assert(MemoryBus::kMaxStations <= DeadlineTree::kSlots);

namespace {
// A core that keeps reporting a deadline at or before `now` after on_time() would stall
// simulated time; after this many calls at one instant the bus reports the faulty station.
constexpr std::uint32_t kMaxCallsPerInstant = 10'000;

bool is_request(const fdl::Telegram& t) {
  return t.type == fdl::FrameType::kToken ||
         (t.type != fdl::FrameType::kShortAck && t.fc.is_request());
}
}  // namespace

const char* to_string(Fate f) {
  switch (f) {
    case Fate::kDelivered: return "delivered";
    case Fate::kDropped: return "dropped";
    case Fate::kCorrupted: return "corrupted";
    case Fate::kDelayed: return "delayed";
    case Fate::kSilenced: return "silenced";
    case Fate::kUnroutable: return "unroutable";
  }
  return "?";
}

struct MemoryBus::Port final : fdl::DecoderSink {
  Station* station = nullptr;
  fdl::Decoder decoder;
  StationCounters counters;
  std::optional<TimePoint> deadline;  // what next_deadline() said last
  // The deadline tree holds an earlier time for this station than `deadline` (a later
  // deadline waits until the earlier entry surfaces, earliest_deadline()).
  bool tree_behind = false;
  TimePoint::rep tree_key = 0;  // the time the tree holds, while tree_behind
  std::optional<std::uint8_t> last_requester;  // SA of the last request it received
  bool silenced = false;
  TimePoint now{};  // valid during a delivery
  TimePoint last_fire{};
  std::uint32_t fires_at_instant = 0;
  std::size_t slot = 0;  // attach order: the tie-break among equal deadlines
  bool woken = false;

  void on_telegram(const fdl::Telegram& t) override {
    ++counters.received;
    if (is_request(t) && t.da != fdl::kBroadcastAddress) last_requester = t.sa;
    station->on_telegram(t, now);
  }
  void on_decode_error(std::error_code e) override {
    ++counters.malformed;
    station->on_malformed_frame(e);  // Station contract step 4
  }
};

struct MemoryBus::Pending {
  TimePoint arrival;
  std::uint64_t sequence = 0;
  std::uint8_t to = 0;
  std::uint32_t frame = 0;  // index into frames_

  // Min-heap on (arrival, sequence): FIFO among simultaneous arrivals.
  friend bool operator<(const Pending& a, const Pending& b) {
    return a.arrival != b.arrival ? a.arrival > b.arrival : a.sequence > b.sequence;
  }
};

MemoryBus::MemoryBus(ManualClock& clock, MemoryBusConfig config)
    : clock_(clock), config_(config), line_free_(clock.now()), alive_(std::make_shared<char>()) {}

MemoryBus::~MemoryBus() = default;

void MemoryBus::attach(Station& station) {
  const std::uint8_t a = station.address();
  if (a >= kMaxStations) {
    throw std::invalid_argument("memory bus: station address " + std::to_string(a) +
                                " is outside 0..126");
  }
  if (ports_[a]) {
    throw std::invalid_argument("memory bus: address " + std::to_string(a) +
                                " is already attached");
  }
  ports_[a] = std::make_unique<Port>();
  ports_[a]->station = &station;
  station.set_send_time_honoured(true);  // transmit() starts each telegram at its send_time()
  Port* p = ports_[a].get();
  p->slot = order_.size();
  order_.push_back(p);
  // A station may outlive the bus (or the other way round): a wake after the bus is gone
  // finds the token expired and does nothing.
  station.set_wake_handler([alive = std::weak_ptr(alive_), this, p] {
    if (!alive.expired()) on_wake(*p);
  });
  refresh_deadline(*p);
}

MemoryBus::Port& MemoryBus::port(std::uint8_t address) {
  return const_cast<Port&>(std::as_const(*this).port(address));
}

const MemoryBus::Port& MemoryBus::port(std::uint8_t address) const {
  if (address >= kMaxStations || !ports_[address]) {
    throw std::out_of_range("memory bus: no station at address " + std::to_string(address));
  }
  return *ports_[address];
}

const StationCounters& MemoryBus::counters(std::uint8_t address) const {
  return port(address).counters;
}

const fdl::DecoderStats& MemoryBus::decoder_stats(std::uint8_t address) const {
  return port(address).decoder.stats();
}

// Marks a bus call: a station that wakes inside it is drained when it returns, so no core
// is ever re-entered from its own on_telegram()/on_time().
struct MemoryBus::InCall {
  MemoryBus& bus;
  explicit InCall(MemoryBus& b) : bus(b) { bus.in_call_ = true; }
  InCall(const InCall&) = delete;
  InCall& operator=(const InCall&) = delete;
  ~InCall() { bus.in_call_ = false; }
};

void MemoryBus::start() {
  {
    const InCall call(*this);
    for (Port* p : order_) {
      p->station->on_time(clock_.now());
      refresh_deadline(*p);
      drain(*p);
    }
  }
  drain_woken();
}

void MemoryBus::on_wake(Port& p) {
  if (!in_call_) {
    drain(p);
  } else if (!p.woken) {
    p.woken = true;
    woken_.push_back(&p);
  }
}

void MemoryBus::drain_woken() {
  // Index loop: a drain may wake further stations, appended behind.
  for (std::size_t i = 0; i < woken_.size(); ++i) {
    woken_[i]->woken = false;
    drain(*woken_[i]);
  }
  woken_.clear();
}

void MemoryBus::refresh_deadline(Port& p) {
  const auto d = p.station->next_deadline();
  if (d == p.deadline) return;
  // A deadline that moves later (a slave's watchdog after each telegram, or none) leaves the
  // tree's earlier entry in place unless it is the tree's front: the entry is a lower bound,
  // brought up to date only once it comes to the front, so a deadline that moves again
  // first costs no tree update. The front entry is always exact, so earliest_deadline() and
  // its tie-break (the lower slot) are as if every entry were.
  const bool later = p.deadline && (!d || *d > *p.deadline);
  if (later || p.tree_behind) {
    if (!p.tree_behind) {
      const auto front = deadlines_.earliest();
      if (!front || front->second != p.slot) {
        p.tree_behind = true;
        p.tree_key = p.deadline->time_since_epoch().count();
      }
    }
    if (p.tree_behind && (!d || d->time_since_epoch().count() > p.tree_key)) {
      p.deadline = d;  // the tree's entry stays strictly earlier: a lower bound
      return;
    }
  }
  p.tree_behind = false;
  p.deadline = d;
  deadlines_.set(p.slot, d);
  // The new front may be an entry that is behind: bring it up to date (and the next).
  for (auto front = deadlines_.earliest(); front && order_[front->second]->tree_behind;
       front = deadlines_.earliest()) {
    Port& q = *order_[front->second];
    q.tree_behind = false;
    deadlines_.set(q.slot, q.deadline);
  }
}

void MemoryBus::drain(Port& p) {
  while (const fdl::Telegram* t = p.station->next_transmit(tx_scratch_)) {
    const auto at = p.station->send_time();
    transmit(p, *t, at && *at > clock_.now() ? *at : clock_.now());
  }
  refresh_deadline(p);
}

std::optional<std::uint8_t> MemoryBus::route(Port& from, const fdl::Telegram& t) {
  if (is_request(t)) return t.da;
  // A reply (short ack or FC bit 6 = 0) answers the request the sender received last.
  const auto to = from.last_requester;
  from.last_requester.reset();
  return to;
}

TimePoint MemoryBus::arrival_time(const Port& from, const fdl::Telegram& t, std::size_t bytes,
                                  TimePoint start) {
  if (!config_.wire_model) return start;
  const BaudRate baud = *config_.wire_model;
  // [IEC 61158-4-3 bus parameters, timing]: TSYN before a request; before a reply the responder's
  // own min TSDR (from its Set_Prm), never less than the configured floor.
  const std::uint32_t gap =
      is_request(t) ? kTsynBits
                    : std::max<std::uint32_t>(config_.min_tsdr_bits, from.station->min_tsdr_bits());
  // Rounded up to the clock tick once per telegram (idle gap + characters).
  line_free_ = std::max(start, line_free_) + bit_time(baud, gap + telegram_bits(bytes));
  return line_free_;
}

void MemoryBus::transmit(Port& from, const fdl::Telegram& t, TimePoint start) {
  ++from.counters.sent;
  // The wire bytes are made only for those who look at them: an observer, or a fault that
  // works on bytes. Otherwise the frame travels as its telegram and only its size counts
  // (encoded_size() makes the same checks as encode(), so a bad telegram throws alike).
  std::span<const std::uint8_t> wire;
  std::size_t size = 0;
  if (!observers_.empty() || !faults_.empty()) {
    size = fdl::encode(t, encode_buf_);
    wire = std::span<const std::uint8_t>(encode_buf_.data(), size);
  } else {
    size = fdl::encoded_size(t);
  }
  BusEvent ev{start, start, from.station->address(), std::nullopt, &t, wire, Fate::kDelivered};
  if (from.silenced) {
    ++from.counters.silenced;
    ev.fate = Fate::kSilenced;
  } else if (const auto to = route(from, t); !to) {
    ++from.counters.unroutable;
    ev.fate = Fate::kUnroutable;
  } else {
    ev.to = to;
    ev.arrival = arrival_time(from, t, size, start);
    if (*to == fdl::kBroadcastAddress) {
      for (Port* p : order_) {
        if (p != &from) schedule(from, p->station->address(), ev.arrival, t, wire);
      }
    } else {
      ev.fate = schedule(from, *to, ev.arrival, t, wire);
    }
  }
  for (const auto& observer : observers_) observer(ev);
}

Fate MemoryBus::schedule(Port& from, std::uint8_t to, TimePoint arrival, const fdl::Telegram& t,
                         std::span<const std::uint8_t> wire) {
  if (to >= kMaxStations || !ports_[to]) return Fate::kDelivered;  // nobody listens there
  Pending p{arrival, 0, to, 0};
  if (faults_.empty()) {  // untouched: the telegram travels, the receiver gets what its bytes
                          // decode to (Decoder::feed_encoded)
    p.sequence = sequence_++;
    p.frame = new_frame();
    Frame& frame = *frames_[p.frame];
    frame.as_telegram = true;
    fdl::copy_telegram(frame.telegram, t);
    queue_.push_back(p);
    std::push_heap(queue_.begin(), queue_.end());
    return Fate::kDelivered;
  }
  // With faults injected every frame travels as bytes and is parsed by the receiver.
  const std::uint8_t sa = from.station->address();
  if (match_fault(FaultKind::kDrop, sa, to)) {
    ++from.counters.dropped;
    return Fate::kDropped;
  }
  Fate fate = Fate::kDelivered;
  p.sequence = sequence_++;
  p.frame = new_frame(wire);
  if (const auto f = match_fault(FaultKind::kCorrupt, sa, to)) {
    Frame& frame = *frames_[p.frame];
    const std::uint32_t bit = f->bit % static_cast<std::uint32_t>(frame.size * 8);
    auto& byte = frame.bytes[bit / 8];
    byte = static_cast<std::uint8_t>(byte ^ (1U << (bit % 8)));
    ++from.counters.corrupted;
    fate = Fate::kCorrupted;
  }
  if (const auto f = match_fault(FaultKind::kDelay, sa, to)) {
    p.arrival += f->delay;
    ++from.counters.delayed;
    if (fate == Fate::kDelivered) fate = Fate::kDelayed;
  }
  queue_.push_back(p);
  std::push_heap(queue_.begin(), queue_.end());
  return fate;
}

std::uint32_t MemoryBus::new_frame() {
  if (free_frames_.empty()) {
    frames_.push_back(std::make_unique<Frame>());
    return static_cast<std::uint32_t>(frames_.size() - 1);
  }
  const std::uint32_t i = free_frames_.back();
  free_frames_.pop_back();
  return i;
}

std::uint32_t MemoryBus::new_frame(std::span<const std::uint8_t> bytes) {
  const std::uint32_t i = new_frame();
  Frame& frame = *frames_[i];
  frame.as_telegram = false;
  frame.size = std::min(bytes.size(), frame.bytes.size());
  std::memcpy(frame.bytes.data(), bytes.data(), frame.size);
  return i;
}

std::optional<Fault> MemoryBus::match_fault(FaultKind kind, std::uint8_t from, std::uint8_t to) {
  for (auto it = faults_.begin(); it != faults_.end(); ++it) {
    const Fault f = it->fault;
    if (f.kind != kind || (f.from && *f.from != from) || (f.to && *f.to != to)) continue;
    if (f.count != 0 && ++it->used >= f.count) faults_.erase(it);  // exhausted
    return f;
  }
  return std::nullopt;
}

FaultId MemoryBus::inject(const Fault& fault) {
  faults_.push_back({next_fault_id_, fault, 0});
  return next_fault_id_++;
}

void MemoryBus::clear_fault(FaultId id) {
  std::erase_if(faults_, [id](const ActiveFault& f) { return f.id == id; });
}

void MemoryBus::clear_faults() { faults_.clear(); }

void MemoryBus::set_silenced(std::uint8_t address, bool silenced) {
  port(address).silenced = silenced;
}

void MemoryBus::send_raw(std::uint8_t to, std::span<const std::uint8_t> bytes) {
  if (to >= kMaxStations || !ports_[to]) return;
  queue_.push_back(Pending{clock_.now(), sequence_++, to, new_frame(bytes)});
  std::push_heap(queue_.begin(), queue_.end());
}

// The frame's slot is given back by the caller after this returns: frames_ keeps its
// elements in place while the receiver's reply schedules new ones.
void MemoryBus::deliver(const Pending& pending) {
  Port& to = *ports_[pending.to];
  if (to.silenced) {
    ++to.counters.silenced;
    return;
  }
  to.now = clock_.now();
  const Frame& frame = *frames_[pending.frame];
  if (frame.as_telegram) {
    to.decoder.feed_encoded(frame.telegram, to);
  } else {
    to.decoder.feed(std::span<const std::uint8_t>(frame.bytes.data(), frame.size), to);
  }
  to.decoder.idle(to);  // TSYN of idle line follows every frame on this bus
                        // ([IEC 61158-4-3 bus parameters, timing])
  drain(to);
}

std::optional<std::pair<TimePoint, MemoryBus::Port*>> MemoryBus::earliest_deadline() const {
  const auto e = deadlines_.earliest();  // exact: refresh_deadline() keeps the front up to date
  if (!e) return std::nullopt;
  return std::pair{e->first, order_[e->second]};
}

std::optional<TimePoint> MemoryBus::next_event_time() const {
  std::optional<TimePoint> t;
  if (!queue_.empty()) t = queue_.front().arrival;
  if (const auto d = earliest_deadline(); d && (!t || d->first < *t)) t = d->first;
  return t;
}

void MemoryBus::fire_deadline(Port& p) {
  const TimePoint now = clock_.now();
  if (p.last_fire == now) {
    if (++p.fires_at_instant > kMaxCallsPerInstant) {
      throw std::logic_error("memory bus: station " + std::to_string(p.station->address()) +
                             " keeps reporting a deadline that has already passed");
    }
  } else {
    p.last_fire = now;
    p.fires_at_instant = 0;
  }
  p.station->on_time(now);
  drain(p);
}

bool MemoryBus::step() { return step_until(TimePoint::max()); }

bool MemoryBus::step_until(TimePoint until) {
  bool stepped = false;
  {
    const InCall call(*this);
    stepped = step_once(until);
  }
  drain_woken();
  return stepped;
}

// Processes the earliest event if it lies at or before `until` (one look at the queue and
// the deadlines, for step() and both run_until()s).
bool MemoryBus::step_once(TimePoint until) {
  const auto deadline = earliest_deadline();
  if (!queue_.empty() && (!deadline || queue_.front().arrival <= deadline->first)) {
    if (queue_.front().arrival > until) return false;
    std::pop_heap(queue_.begin(), queue_.end());
    const Pending p = queue_.back();
    queue_.pop_back();
    if (p.arrival > clock_.now()) clock_.set(p.arrival);
    deliver(p);
    free_frames_.push_back(p.frame);
    return true;
  }
  if (!deadline || deadline->first > until) return false;
  if (deadline->first > clock_.now()) clock_.set(deadline->first);
  fire_deadline(*deadline->second);
  return true;
}

void MemoryBus::run_until(TimePoint until) {
  while (step_until(until)) {
  }
  if (until > clock_.now()) clock_.set(until);
}

}  // namespace rs4sim::dp::link
