#pragma once
// In-memory PROFIBUS: one master and up to 125 slaves in one process, on a ManualClock.
//
// Every telegram a station transmits is encoded to wire bytes ([IEC 61158-4-3 frame formats]) and
// reaches the receiving station through its own fdl::Decoder, so corrupted frames are rejected
// exactly as on a real line. While any fault is injected every frame is fed byte for byte; on a
// bus without faults a frame travels as its telegram and the decoder's feed_encoded() delivers
// what those bytes decode to (the same telegram, errors and statistics) without parsing them
// again. Routing: a request or token goes to the station with its DA
// (DA 127 = broadcast to every other station, [IEC 61158-4-3 addresses, SAPs]); a reply (FC bit 6
// = 0) or a short acknowledgement E5 goes to the station whose request the sender received last
// ([IEC 61158-4-3 short acknowledgement]).
//
// Time is simulated: step() jumps the clock to the next event (a delivery or a station
// deadline); run_until() repeats that up to a time, so a 30 s scenario runs in
// milliseconds, deterministically. Optionally the bus models the wire: each telegram takes
// 11 bit per character ([IEC 61158-4-3 UART character] [IEC 61158-2 baud rates]) after TSYN = 33
// bit idle before a request or min TSDR before a reply ([IEC 61158-4-3 bus parameters, timing]),
// and the line carries one telegram at a time.
//
// Fault injection: drop, corrupt (flip one bit; the receiver's decoder must reject it),
// delay, and silence a station (it neither sends nor receives).

#include "dp/fdl/decoder.h"
#include "dp/link/counters.h"
#include "dp/link/deadline_tree.h"
#include "dp/station.h"
#include "dp/time/baud_rate.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace rs4sim::dp::link {

struct MemoryBusConfig {
  // nullopt: telegrams arrive at the instant they are sent (pure logic tests).
  std::optional<BaudRate> wire_model;
  // Floor for the gap before a reply; the responder's Station::min_tsdr_bits() applies
  // when larger (a slave reports what Set_Prm byte 3 set, [IEC 61158-4-3 bus parameters, timing]).
  std::uint32_t min_tsdr_bits = kMinTsdrBits;
};

enum class FaultKind : std::uint8_t { kDrop, kCorrupt, kDelay };

// Affects the next `count` telegrams matching from/to (0 = until cleared).
struct Fault {
  FaultKind kind = FaultKind::kDrop;
  std::optional<std::uint8_t> from;  // sender address; nullopt = any sender
  std::optional<std::uint8_t> to;    // receiver address; nullopt = any receiver
  std::uint32_t count = 1;
  Duration delay{};       // kDelay: added to the arrival time
  std::uint32_t bit = 0;  // kCorrupt: bit index into the frame (mod its size)
};
using FaultId = std::uint32_t;

// What happened to one transmitted telegram, for observers (demo narration, capture).
enum class Fate : std::uint8_t {
  kDelivered,
  kDropped,
  kCorrupted,
  kDelayed,
  kSilenced,
  kUnroutable
};
const char* to_string(Fate f);

struct BusEvent {
  TimePoint time;     // when the sender handed it to the bus (at its send_time(), if later)
  TimePoint arrival;  // when it reaches the receiver(s)
  std::uint8_t from = 0;
  std::optional<std::uint8_t> to;  // 127 = broadcast; nullopt = unroutable
  const fdl::Telegram* telegram = nullptr;
  std::span<const std::uint8_t> wire;  // the encoded bytes (before corruption)
  Fate fate = Fate::kDelivered;
};
using BusObserver = std::function<void(const BusEvent&)>;

class MemoryBus {
 public:
  static constexpr std::size_t kMaxStations = 127;  // addresses 0..126

  explicit MemoryBus(ManualClock& clock, MemoryBusConfig config = {});
  ~MemoryBus();
  MemoryBus(const MemoryBus&) = delete;
  MemoryBus& operator=(const MemoryBus&) = delete;

  // Attaches a station by its address() and installs its wake handler (a station that
  // changes outside a bus call is drained and its deadline re-read at once; during a bus
  // call, when that call returns). Throws std::invalid_argument for an address above 126
  // or already in use. The station must outlive the bus.
  void attach(Station& station);

  // Calls on_time() once on every station (the contract's "at least once after start").
  void start();

  // Processes the earliest pending event and moves the clock to it. false = nothing pending.
  bool step();
  // Processes every event up to `until`, then sets the clock to `until` (if later).
  void run_until(TimePoint until);
  void run_for(Duration d) { run_until(clock_.now() + d); }
  // Steps until done() holds or the next event lies after `until` (then runs to `until`);
  // after_step() runs before each check (a harness collects the master's events there).
  // Returns done() at the end.
  bool run_until(const std::function<bool()>& done, TimePoint until,
                 const std::function<void()>& after_step) {
    return run_until_with(done, until, after_step);
  }
  // The same loop for callables the compiler sees through (no type-erased call per step: a
  // harness checks `done` after every one of the 250 events of a 125-slave cycle).
  template <class Done, class AfterStep>
  bool run_until_with(Done&& done, TimePoint until, AfterStep&& after_step) {
    after_step();
    while (!done()) {
      if (!step_until(until)) {  // the next event lies after `until`
        if (until > clock_.now()) clock_.set(until);
        after_step();
        return done();
      }
      after_step();
    }
    return true;
  }
  [[nodiscard]] std::optional<TimePoint> next_event_time() const;

  FaultId inject(const Fault& fault);
  void clear_fault(FaultId id);
  void clear_faults();
  void set_silenced(std::uint8_t address, bool silenced);
  // Puts arbitrary bytes (≤ 255, e.g. a hand-made or garbage frame) on the wire to the
  // station at `to`, arriving now; they go through its decoder like any
  // frame. For tests and fuzzing. Unknown `to`: ignored.
  void send_raw(std::uint8_t to, std::span<const std::uint8_t> bytes);

  // Observers see every transmitted telegram, in the order they were added.
  void add_observer(BusObserver observer) { observers_.push_back(std::move(observer)); }

  // Counters of an attached station; throws std::out_of_range for an unknown address.
  [[nodiscard]] const StationCounters& counters(std::uint8_t address) const;
  [[nodiscard]] const fdl::DecoderStats& decoder_stats(std::uint8_t address) const;
  [[nodiscard]] std::size_t station_count() const { return order_.size(); }
  [[nodiscard]] TimePoint now() const { return clock_.now(); }

 private:
  struct Port;
  struct Pending;
  struct InCall;
  struct ActiveFault {
    FaultId id;
    Fault fault;
    std::uint32_t used = 0;
  };

  Port& port(std::uint8_t address);
  const Port& port(std::uint8_t address) const;
  void drain(Port& p);
  void on_wake(Port& p);
  bool step_until(TimePoint until);  // step() if the next event lies at or before `until`
  bool step_once(TimePoint until);
  void drain_woken();
  // `start`: when the sender hands it to the line (now, or its later send_time()).
  void transmit(Port& from, const fdl::Telegram& t, TimePoint start);
  std::optional<std::uint8_t> route(Port& from, const fdl::Telegram& t);
  TimePoint arrival_time(const Port& from, const fdl::Telegram& t, std::size_t bytes,
                         TimePoint start);
  Fate schedule(Port& from, std::uint8_t to, TimePoint arrival, const fdl::Telegram& t,
                std::span<const std::uint8_t> wire);
  std::optional<Fault> match_fault(FaultKind kind, std::uint8_t from, std::uint8_t to);
  std::uint32_t new_frame();
  std::uint32_t new_frame(std::span<const std::uint8_t> bytes);
  void deliver(const Pending& p);
  void fire_deadline(Port& p);
  void refresh_deadline(Port& p);
  [[nodiscard]] std::optional<std::pair<TimePoint, Port*>> earliest_deadline() const;

  ManualClock& clock_;
  MemoryBusConfig config_;
  std::array<std::unique_ptr<Port>, kMaxStations> ports_;
  std::vector<Port*> order_;    // attach order = deterministic tie-break for deadlines
  std::vector<Pending> queue_;  // binary heap on (arrival, sequence), small records
  // The frames in flight, by index, each on the heap once (stable while a delivery
  // schedules new ones) and reused; indexing is one load (a deque's was a division).
  // A frame no fault touched travels as the telegram it was encoded from and reaches the
  // receiver through Decoder::feed_encoded (the same result as decoding its bytes, without
  // parsing them again); a frame a fault touched (corrupted or delayed) and raw bytes
  // (send_raw) travel as bytes and go through the receiver's full checks.
  struct Frame {
    std::array<std::uint8_t, fdl::kMaxTelegramSize> bytes;
    std::size_t size = 0;
    bool as_telegram = false;  // `telegram` holds the frame, `bytes` are unused
    fdl::Telegram telegram;
  };
  std::vector<std::unique_ptr<Frame>> frames_;
  std::vector<std::uint32_t> free_frames_;
  std::vector<ActiveFault> faults_;
  FaultId next_fault_id_ = 1;
  std::uint64_t sequence_ = 0;
  TimePoint line_free_{};
  DeadlineTree deadlines_;  // slot = attach order
  std::array<std::uint8_t, fdl::kMaxTelegramSize> encode_buf_{};
  fdl::Telegram tx_scratch_;  // for stations that hand out copies (Station::next_transmit)
  std::vector<Port*> woken_;  // woke during a bus call: drained when the call returns
  bool in_call_ = false;
  std::shared_ptr<char> alive_;  // wake handlers hold a weak_ptr to it
  std::vector<BusObserver> observers_;
};

}  // namespace rs4sim::dp::link
