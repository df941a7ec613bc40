#pragma once
// PROFIBUS-DP class 1 master, sans-I/O ([IEC 61158-4-3 bus parameters, timing, FCB/FCV, token]
// [IEC 61158-6-3 class 1 master]; [docs/design.md#principles]).
//
// Bus access. The master is meant to be the only active station on its link. With
// `claim_token` it starts as [IEC 61158-4-3 token, bus start, token] prescribe for a lone master:
// it listens for the token-lost timeout TTO (any traffic restarts the wait) and claims the token by
// sending `DC TS TS` twice, TSYN apart. It then keeps the token for good: it neither passes it to
// itself between cycles nor GAP-polls for other masters (documented simplification).
//
// Cycle. Every `cycle_target` a poll cycle starts: queued Global_Control broadcasts go
// first (SDN, then TID2 idle), then each slave gets one turn in configuration order
// (slave_handler.h). At most one request is outstanding. Its slot deadline is
// send time + request wire time + TSL + wire time of the longest acceptable reply: links
// deliver a reply only when it is complete, so the wait for the first character (TSL,
// [IEC 61158-4-3 bus parameters, timing]) is extended by the reply's own transmission time. After a
// reply the next request waits TID1 (≥ TSYN): on a link that honours Station::send_time() the
// master builds that request at once, as of the reply's end + TID1, and hands it out with that
// send time (no deadline step of its own for the idle time); elsewhere it builds it when its
// deadline at that time comes. On expiry the same telegram (same FCB) is re-sent up
// to max_retry_limit times, except a first frame (FCV=0), which is not retried
// ([IEC 61158-4-3 FCB/FCV]); then the slave counts as not answering
// ([IEC 61158-6-3 slave supervision]).
//
// Results. Events are queued and drained with take_events() (events.h). DPV1 Read/Write
// return a request id at once; the outcome arrives later as a Dpv1Result event (a
// completion through the event queue rather than a callback, so user code never runs
// inside the core).

#include "dp/fdl/fcb.h"
#include "dp/master/event_queue.h"
#include "dp/master/events.h"
#include "dp/master/master_config.h"
#include "dp/master/slave_handler.h"
#include "dp/pdu/global_control.h"
#include "dp/station.h"

#include <boost/outcome/std_result.hpp>

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <system_error>
#include <vector>

namespace rs4sim::dp::master {

enum class MasterPhase : std::uint8_t { kListening, kClaimingToken, kRunning };
enum class OperatingMode : std::uint8_t { kOperate, kClear };

struct MasterCounters {
  std::uint64_t cycles = 0;
  std::uint64_t telegrams_sent = 0;     // requests, retries, broadcasts and tokens
  std::uint64_t replies = 0;            // replies matched to the outstanding request
  std::uint64_t slot_timeouts = 0;      // TSL expiries (each one a retry or a no-answer)
  std::uint64_t ignored_telegrams = 0;  // not for us, requests of other stations, late replies
  std::uint64_t malformed_frames = 0;   // reported by the link's decoder
  std::uint64_t global_controls = 0;
  Duration last_cycle{};
  Duration max_cycle{};
};

class Master final : public Station {
 public:
  // Throws std::system_error with the validate() error for an invalid configuration.
  explicit Master(MasterConfig config);

  // --- Station (the link's side) ---
  [[nodiscard]] std::uint8_t address() const override { return config_.address; }
  void on_telegram(const fdl::Telegram& t, TimePoint now) override;
  void on_time(TimePoint now) override;
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override;
  std::optional<fdl::Telegram> take_transmit() override;
  const fdl::Telegram* next_transmit(fdl::Telegram& scratch) override;
  [[nodiscard]] std::optional<TimePoint> send_time() const override;
  // A frame the link's decoder rejected ([IEC 61158-4-3 frame reception]): counted; a garbled reply
  // is handled like a missing one, by the slot time and a retry with the same FCB
  // ([IEC 61158-4-3 FCB/FCV]).
  void on_malformed_frame(std::error_code why) override;

  // --- User API ---
  // Outputs sent with every Data_Exchange; length must equal the configured length.
  std::error_code set_outputs(std::uint8_t slave, std::span<const std::uint8_t> outputs);
  // Inputs of the last Data_Exchange; empty if unknown or not in data exchange.
  [[nodiscard]] std::span<const std::uint8_t> inputs(std::uint8_t slave) const;
  // A copy of the slave's status with its buffers; poll_state() for the state alone.
  [[nodiscard]] std::optional<SlaveStatus> slave_status(std::uint8_t slave) const;
  // The slave's start-up / data exchange state without copying anything; nullopt if unknown.
  [[nodiscard]] std::optional<PollState> poll_state(std::uint8_t slave) const;
  [[nodiscard]] std::vector<std::uint8_t> slave_addresses() const;
  // Queues a Global_Control broadcast ([IEC 61158-6-3 Global_Control]) for the start of the next
  // cycle. kBadArgument for reserved command bits, kQueueFull beyond 8 pending.
  std::error_code global_control(const pdu::GlobalControl& gc);
  // CLEAR: outputs sent as zeros (empty for Fail_Safe slaves) and GC Clear broadcast;
  // OPERATE: outputs as set and GC Operate ([IEC 61158-6-3 Global_Control, Data_Exchange]).
  void set_operating_mode(OperatingMode mode);
  [[nodiscard]] OperatingMode operating_mode() const { return mode_; }
  // DPV1 C1 Read (length 1..240) / Write (1..240 bytes) ([IEC 61158-6-3 MSAC_C1]). Errors now:
  // kUnknownSlave, kNotInDataExchange, kDpv1NotEnabled, kBadArgument, kQueueFull; later outcomes
  // come as a Dpv1Result event with the returned id.
  boost::outcome_v2::std_result<Dpv1RequestId> read(std::uint8_t slave, std::uint8_t slot,
                                                    std::uint8_t index, std::uint8_t length);
  boost::outcome_v2::std_result<Dpv1RequestId> write(std::uint8_t slave, std::uint8_t slot,
                                                     std::uint8_t index,
                                                     std::span<const std::uint8_t> data);
  // Manual alarm acknowledgement (auto_alarm_ack = false), by (slot, type, Seq_Nr).
  std::error_code acknowledge_alarm(std::uint8_t slave, std::uint8_t slot, std::uint8_t alarm_type,
                                    std::uint8_t seq_nr);
  // Moves all queued events to `out` (appends).
  void take_events(std::vector<MasterEvent>& out) { events_.take(out); }
  std::vector<MasterEvent> take_events();
  [[nodiscard]] std::uint64_t events_dropped() const { return events_.dropped(); }

  [[nodiscard]] MasterPhase phase() const { return phase_; }
  [[nodiscard]] const MasterCounters& counters() const { return counters_; }
  [[nodiscard]] const MasterConfig& config() const { return config_; }

 private:
  struct Outstanding {
    std::size_t slave = 0;
    Request request;
    TimePoint deadline;
    unsigned retries = 0;
  };
  SlaveHandler* find(std::uint8_t address);
  [[nodiscard]] const SlaveHandler* find(std::uint8_t address) const;
  SlaveContext context();
  void transmit(const fdl::Telegram& t);
  void queue_copy(const fdl::Telegram& t);
  // Queues outstanding_'s request itself (handed out from there, no copy).
  void transmit_request();
  // Before outstanding_ changes: a queued request not yet taken is copied into tx_.
  void keep_queued_request();
  // Sends the request built in outstanding_ to slaves_[slave].
  void send_request(std::size_t slave, TimePoint now);
  Request& begin_outstanding();  // marks the slot in use, for next_request() to fill
  void on_slot_expired(TimePoint now);
  void run_bus(TimePoint now);
  void start_cycle(TimePoint now);
  void end_cycle(TimePoint now);
  void send_global_control(const pdu::GlobalControl& gc, TimePoint now);
  void claim_token_step(TimePoint now);
  boost::outcome_v2::std_result<Dpv1RequestId> submit(std::uint8_t slave, Dpv1Job job);

  MasterConfig config_;
  std::vector<SlaveHandler> slaves_;
  std::array<std::int16_t, 128> index_{};  // address → slaves_ index, -1 if none
  fdl::FcbInitiator fcb_;
  EventQueue events_;
  // tx_[tx_head_..] wait for the link; the storage is reused (cleared by the next transmit()
  // once all were taken, so a view handed out stays valid until the next call).
  std::vector<fdl::Telegram> tx_;
  std::size_t tx_head_ = 0;
  bool request_queued_ = false;  // after tx_: outstanding_->request.telegram
  MasterPhase phase_;
  OperatingMode mode_ = OperatingMode::kOperate;
  bool started_ = false;
  TimePoint listen_until_{};
  unsigned tokens_sent_ = 0;
  // The request waiting for its reply (when outstanding_active_); the slot is reused, so a
  // request is not constructed (zero-filled) afresh each time.
  Outstanding outstanding_;
  bool outstanding_active_ = false;
  TimePoint next_send_{};
  // The telegrams queued now were built ahead, as of this time (send_time()); set by a reply on
  // a link that honours send times, cleared by on_time(), whose telegrams are due at once.
  std::optional<TimePoint> built_for_;
  bool in_cycle_ = false;
  std::size_t cursor_ = 0;
  bool turn_open_ = false;
  bool cycle_sent_ = false;
  TimePoint cycle_start_{};
  TimePoint next_gc_{};
  std::deque<pdu::GlobalControl> gc_queue_;
  Dpv1RequestId next_id_ = 1;
  MasterCounters counters_;
};

}  // namespace rs4sim::dp::master
