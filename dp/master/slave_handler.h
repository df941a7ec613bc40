#pragma once
// The master's view of one slave: start-up, cyclic Data_Exchange and supervision
// ([IEC 61158-6-3 master start-up of a slave, class 1 master cycle, slave supervision]
// [pyprofibus dp_master.py]), with the DPV1 C1 client and the alarm tracker.
//
// Start-up ([IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py]): kStatusRequest
// (FDL_Status, optional) → kReadDiag (Slave_Diag, FCB first frame) → kSetPrm → kChkCfg → kWaitReady
// (Slave_Diag until Prm_Req, Stat_Diag, Station_Not_Ready, Prm/Cfg_Fault clear and Master_Add =
// own) → kDataExchange. The master gives each slave one *turn* per poll cycle; within a turn the
// handler may chain start-up steps (Diag → Set_Prm → Chk_Cfg → Diag) and, in data exchange, adds at
// most one Slave_Diag (after DH), one Alarm_Ack and one DPV1 exchange after the Data_Exchange
// ([IEC 61158-6-3 class 1 master cycle]).

#include "dp/fdl/fcb.h"
#include "dp/master/alarm_tracker.h"
#include "dp/master/dpv1_client.h"
#include "dp/master/event_queue.h"
#include "dp/master/master_config.h"
#include "dp/master/reply.h"
#include "dp/pdu/slave_diag.h"

#include <cstdint>
#include <optional>
#include <span>
#include <system_error>

namespace rs4sim::dp::master {

enum class PollState : std::uint8_t {
  kStatusRequest,  // [IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py] step 0:
                   // FDL_Status
  kReadDiag,       // step 1: first Slave_Diag (ident, Master_Add)
  kSetPrm,         // step 2
  kChkCfg,         // step 3
  kWaitReady,      // step 4: Slave_Diag until ready
  kDataExchange,   // step 5: cyclic Data_Exchange
};
const char* to_string(PollState s);

enum class RequestKind : std::uint8_t {
  kFdlStatus,
  kDiag,
  kSetPrm,
  kChkCfg,
  kDataExchange,
  kDpv1,
  kAlarmAck
};

struct Request {
  fdl::Telegram telegram;
  RequestKind kind = RequestKind::kFdlStatus;
  std::size_t max_reply_bytes = 6;  // longest reply accepted, for the slot deadline
};

struct PollCounters {
  std::uint64_t requests = 0;        // telegrams sent to the slave (retries included)
  std::uint64_t retries = 0;         // re-sent after a missing reply ([IEC 61158-4-3 FCB/FCV])
  std::uint64_t no_answer = 0;       // gave up after max_retry_limit retries
  std::uint64_t data_exchanges = 0;  // successful Data_Exchange cycles
  std::uint64_t diag_reads = 0;
  std::uint64_t entered_data_exchange = 0;
  std::uint64_t left_data_exchange = 0;  // lost slave or re-parameterisation
                                         // ([IEC 61158-6-3 slave supervision])
  // Replies that do not fit their request (wrong kind, length or SAPs); a negative reply
  // counts in negative_replies only.
  std::uint64_t invalid_responses = 0;
  // Replies with a negative status: RS (SAP not enabled), RR (no resources), UE (user error)
  // ([IEC 61158-4-3 frame control, response status]).
  std::uint64_t negative_replies = 0;
};

struct SlaveStatus {
  std::uint8_t address = 0;
  PollState state = PollState::kStatusRequest;
  const char* state_name = "";
  PollCounters counters;
  fdl::DataUnit last_diag;     // the last Slave_Diag DU received
  std::error_code last_error;  // the last fault (kept after recovery)
  std::size_t alarms_outstanding = 0;
  std::size_t dpv1_queued = 0;
};

// What the handler needs from its master for one call.
struct SlaveContext {
  std::uint8_t master_address;
  fdl::FcbInitiator& fcb;
  EventQueue& events;
  bool clear_mode;  // outputs as zeros (or empty for Fail_Safe slaves,
                    // [IEC 61158-6-3 Data_Exchange])
  bool auto_alarm_ack;
  Duration ready_timeout;
};

class SlaveHandler {
 public:
  static constexpr unsigned kMaxRequestsPerTurn = 8;

  SlaveHandler(const SlaveEntry& config, bool fdl_status_first);

  void begin_turn() { turn_ = {}; }
  // The next request of this turn, built into `out` (the master's retry slot); false when
  // the turn is over (`out` may then hold anything).
  bool next_request(SlaveContext& ctx, TimePoint now, Request& out);
  // The reply to the last request (already checked to come from this slave).
  void on_reply(SlaveContext& ctx, const Reply& r, TimePoint now);
  // No reply after all retries ([IEC 61158-6-3 slave supervision]).
  void on_no_answer(SlaveContext& ctx);
  void count_retry() {
    ++counters_.retries;
    ++counters_.requests;
  }
  // Housekeeping once per cycle (DPV1 timeouts).
  void on_cycle_start(SlaveContext& ctx, TimePoint now);

  std::error_code set_outputs(std::span<const std::uint8_t> outputs);
  // The inputs of the last Data_Exchange; empty while not in data exchange.
  [[nodiscard]] std::span<const std::uint8_t> inputs() const;
  std::error_code submit(Dpv1Job job);
  std::error_code acknowledge_alarm(std::uint8_t slot, std::uint8_t type, std::uint8_t seq_nr);

  [[nodiscard]] std::uint8_t address() const { return config_.address; }
  [[nodiscard]] PollState state() const { return state_; }
  [[nodiscard]] bool in_data_exchange() const { return state_ == PollState::kDataExchange; }
  [[nodiscard]] const SlaveEntry& config() const { return config_; }
  [[nodiscard]] SlaveStatus status() const;

 private:
  struct Turn {
    unsigned count = 0;
    bool dx = false, diag = false, alarm = false, dpv1 = false;
  };
  bool make(Request& out, SlaveContext& ctx, RequestKind kind, fdl::FrameControl fc,
            std::optional<std::uint8_t> dsap, std::span<const std::uint8_t> data,
            std::size_t max_reply) const;
  bool startup_request(SlaveContext& ctx, Request& out);
  bool cyclic_request(SlaveContext& ctx, TimePoint now, Request& out);
  bool data_exchange_request(SlaveContext& ctx, Request& out) const;
  [[nodiscard]] PollState initial_state() const;
  [[nodiscard]] std::uint8_t alarm_dsap() const;

  // Reply handlers (slave_replies.cpp).
  void on_status_reply(SlaveContext& ctx, const Reply& r);
  void on_diag_reply(SlaveContext& ctx, const Reply& r);
  void on_first_diag(SlaveContext& ctx, const pdu::SlaveDiag& d);
  void on_ready_diag(SlaveContext& ctx, const pdu::SlaveDiag& d);
  void on_cyclic_diag(SlaveContext& ctx, const pdu::SlaveDiag& d);
  void on_prm_cfg_reply(SlaveContext& ctx, const Reply& r, TimePoint now);
  void on_dx_reply(SlaveContext& ctx, const Reply& r);
  void record_diag(SlaveContext& ctx, std::span<const std::uint8_t> du, bool always_report);

  // Transitions.
  void fault(SlaveContext& ctx, std::error_code reason);
  void restart(SlaveContext& ctx, std::error_code reason, PollState next);
  void enter_data_exchange(SlaveContext& ctx);
  void leave_data_exchange(SlaveContext& ctx, std::error_code reason, PollState next);

  SlaveEntry config_;
  fdl::DataUnit prm_du_;
  bool fdl_status_first_;
  PollState state_;
  RequestKind last_kind_ = RequestKind::kFdlStatus;
  Turn turn_;
  bool continue_ = false;     // chain the next start-up step in this turn
  bool diag_needed_ = false;  // DH seen or Stat_Diag set ([IEC 61158-6-3 Data_Exchange])
  TimePoint wait_ready_since_{};
  fdl::DataUnit outputs_;
  fdl::DataUnit inputs_;
  fdl::DataUnit last_diag_;
  std::error_code last_error_;
  std::error_code reported_;  // last fault reported as an event (reset in DX)
  PollCounters counters_;
  Dpv1Client dpv1_;
  AlarmTracker alarms_;
};

}  // namespace rs4sim::dp::master
