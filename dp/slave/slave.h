#pragma once
// dp::Slave — the DP/DPV1 slave state machine
// ([IEC 61158-4-3 bus parameters, timing, FCB/FCV, token, frame reception]
// [IEC 61158-6-3 DP-V0 services, DPV1]).
//
// Sans-I/O ([docs/design.md#principles]): telegrams and time in (dp::Station), reply telegrams and
// the next deadline out. The device behind it is a SlaveApplication.
//
// Behaviour in one place (decisions on points the sources leave open are marked DECISION):
// * Address filter ([IEC 61158-4-3 frame reception]): own address; DA 127 only for SDN
// (Global_Control), never
//   answered; responses and tokens are ignored.
// * FCB/FCV ([IEC 61158-4-3 FCB/FCV]): a repeat (same SA, FCV=1, same FCB) gets the stored reply
// again and is
//   not executed a second time.
// * States Wait_Prm → Wait_Cfg → Data_Exch ([IEC 61158-6-3 slave state machine]). A service the
// current state does not
//   allow, or a DP service from a master that does not own the slave, is answered RS
//   (SD1 FC 03) like a SAP that is not activated ([IEC 61158-6-3 slave state machine] DX trace,
//   [IEC 61158-6-3 MSAC_C1 polling] VPC3 SAP list).
//   DECISION: Chk_Cfg refused → Wait_Prm; Set_Prm in Data_Exch → Wait_Cfg; after the
//   watchdog the slave forgets its master (Master_Add FF).
// * Watchdog ([IEC 61158-6-3 watchdog]): T_WD = F1·F2·10 ms (1 ms with WD_Base_1ms), retriggered by
// every
//   telegram to this station from the owning master; expiry at exactly T_WD.
// * Diagnosis ([IEC 61158-6-3 Slave_Diag]): station status computed from the state; new diagnosis
// (device
//   blocks, an alarm, Not_Supported) sets the diag flag → Data_Exchange answers DH until
//   the owner fetched the diagnosis; Stat_Diag keeps the flag set.
// * DPV1 ([IEC 61158-6-3 MSAC_C1, MSAC_C1 polling, DPV1 alarms, status PDUs]): C1 on SAP 51
// (Alarm_Ack also on SAP 50 with extra_alarm_sap) with
//   the poll pattern of [IEC 61158-6-3 MSAC_C1 polling]: a request is answered SC, the response
//   goes out on a later poll; alarms per alarm_queue.h. MSAC_C2 ([IEC 61158-6-3 MSAC_C2]): one
//   connection, RM on SAP 49.

#include "dp/fdl/fcb.h"
#include "dp/pdu/set_prm.h"
#include "dp/slave/alarm_queue.h"
#include "dp/slave/slave_application.h"
#include "dp/slave/slave_config.h"
#include "dp/station.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

namespace rs4sim::dp::slave {

// fdl::DataUnit as a byte span (boost::container::static_vector is not a std range here).
[[nodiscard]] inline std::span<const std::uint8_t> bytes_of(const fdl::DataUnit& d) {
  return {d.data(), d.size()};
}

struct Counters {
  std::uint64_t telegrams_seen = 0;      // every telegram given to on_telegram()
  std::uint64_t for_other_stations = 0;  // DA not ours (and not a broadcast we take)
  std::uint64_t broadcasts = 0;          // SDN to 127 evaluated
  std::uint64_t ignored = 0;             // responses, tokens, unsupported broadcasts
  std::uint64_t malformed_dropped = 0;   // reported by the link (on_malformed_frame)
  std::uint64_t repeats_answered = 0;    // FCB repeats answered from the stored reply
  std::uint64_t rs_replies = 0;          // SAP not activated / wrong state / not owner
  std::uint64_t watchdog_expiries = 0;
  std::uint64_t output_length_errors = 0;   // Data_Exchange DU ≠ configured output length
  std::uint64_t default_sap = 0;            // Data_Exchange requests
  std::array<std::uint64_t, 64> per_sap{};  // requests per DSAP 0…63
};

struct Transition {
  State from;
  State to;
  TransitionReason why;
  TimePoint at;
};

class Slave final : public Station, public SlaveControl {
 public:
  // Throws std::system_error (dp.slave category) if `config.validate()` fails.
  Slave(const Config& config, SlaveApplication& app);
  Slave(const Slave&) = delete;  // the application holds a SlaveControl& to this object
  Slave& operator=(const Slave&) = delete;

  // Power-up of the same slave at `address`: Wait_Prm, no master, parameters, configuration,
  // diagnosis, alarms, acyclic jobs and counters as after construction; the configuration, the
  // application (its SlaveControl& stays valid), the trace hook and the wake handler are kept.
  // Throws std::system_error (dp.slave category) if the address is not a station address.
  void restart(std::uint8_t address);

  // ---- Station ----
  [[nodiscard]] std::uint8_t address() const override { return address_; }
  void on_telegram(const fdl::Telegram& t, TimePoint now) override;
  void on_time(TimePoint now) override;
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override;
  std::optional<fdl::Telegram> take_transmit() override;
  // The reply in place (no copy); it stays in tx_ until the next request replaces it.
  const fdl::Telegram* next_transmit(fdl::Telegram& scratch) override;
  // The link dropped a frame that failed the [IEC 61158-4-3 frame reception] checks: counted
  // (malformed_dropped).
  void on_malformed_frame(std::error_code why) override;
  // min TSDR in Tbit: config default until Set_Prm byte 3 changes it
  // ([IEC 61158-4-3 bus parameters, timing]).
  [[nodiscard]] std::uint16_t min_tsdr_bits() const override { return min_tsdr_; }

  // ---- SlaveControl (see slave_application.h) ----
  std::error_code complete_acyclic(AcyclicChannel channel, const AcyclicResult& r) override;
  std::error_code submit_alarm(const AlarmRequest& a) override;
  std::error_code set_device_diagnosis(std::span<const std::uint8_t> blocks, bool ext_diag,
                                       bool stat_diag) override;

  // ---- observation ----
  [[nodiscard]] State state() const { return state_; }
  [[nodiscard]] std::uint8_t master_address() const { return master_; }
  // Tbit ([IEC 61158-4-3 bus parameters, timing])
  [[nodiscard]] std::uint8_t min_tsdr() const { return min_tsdr_; }
  [[nodiscard]] std::optional<Duration> watchdog_time() const { return wd_time_; }
  [[nodiscard]] bool diag_flag() const { return diag_flag_ || stat_diag_; }
  [[nodiscard]] bool dpv1_active() const { return dpv1_.has_value(); }
  [[nodiscard]] const AlarmQueue& alarms() const { return alarms_; }
  [[nodiscard]] bool c2_connected() const { return c2_.bound && c2_.established; }
  // The Slave_Diag DU the slave would send now (without fetching it).
  [[nodiscard]] fdl::DataUnit diagnosis() const;
  [[nodiscard]] const Counters& counters() const { return counters_; }
  // Transition trace (state names via to_string()); no printing in the core.
  void set_trace(std::function<void(const Transition&)> hook) { trace_ = std::move(hook); }

 private:
  struct AcyclicJob {
    enum class Phase : std::uint8_t { kIdle, kWaitingForApp, kReady };
    Phase phase = Phase::kIdle;
    std::uint8_t function = 0;  // function number of the request
    fdl::DataUnit request;      // repeated identical request = poll
                                // ([IEC 61158-6-3 MSAC_C1 polling])
    fdl::DataUnit response;
    bool close_after_send = false;  // C2 Abort / refused Initiate
  };
  struct C2Connection {
    bool bound = false;
    bool established = false;  // Initiate.res produced
    bool first_write_seen = false;
    std::uint8_t master = 0;
    std::uint8_t master_sap = 0;
    Duration send_timeout{};
    TimePoint deadline{};
    AcyclicJob job;
  };

  // dispatch (slave.cpp)
  void handle_request(const fdl::Telegram& t, TimePoint now);
  void dispatch(const fdl::Telegram& t, TimePoint now);
  void dispatch_dp_sap(const fdl::Telegram& t, TimePoint now);
  void check_timers(TimePoint now);
  void enter(State to, TransitionReason why, TimePoint now);
  void reset_parameters(bool keep_master);
  void retrigger_watchdog(std::uint8_t sa, TimePoint now);
  void promote_alarm();
  void fault_to_wait_prm(TransitionReason why, bool keep_master, TimePoint now);
  [[nodiscard]] bool is_owner(std::uint8_t sa) const { return master_ == sa; }
  // replies
  fdl::Telegram& new_reply();  // every reply is built here (tx_, not yet handed out)
  void reply_short_ack();
  void reply_status(const fdl::Telegram& req, fdl::ResponseStatus st);
  fdl::DataUnit& reply_data(const fdl::Telegram& req, fdl::ResponseStatus st);
  void reply_rs(const fdl::Telegram& req);

  // DP-V0 services (slave_dpv0.cpp)
  void on_set_prm(const fdl::Telegram& t, TimePoint now);
  PrmVerdict judge_prm(const pdu::SetPrm& prm, TimePoint now);
  void take_over_prm(const pdu::SetPrm& prm, std::uint8_t master, TimePoint now);
  void on_chk_cfg(const fdl::Telegram& t, TimePoint now);
  void on_get_cfg(const fdl::Telegram& t);
  void on_slave_diag(const fdl::Telegram& t);
  void on_global_control(const fdl::Telegram& t, TimePoint now);
  void on_data_exchange(const fdl::Telegram& t, TimePoint now);
  void on_read_io(const fdl::Telegram& t, bool inputs, TimePoint now);
  void on_set_slave_add(const fdl::Telegram& t, TimePoint now);
  void fill_inputs(fdl::DataUnit& out, TimePoint now);

  // DPV1 (slave_dpv1.cpp, slave_c2.cpp)
  void on_msac_c1(const fdl::Telegram& t, TimePoint now);
  void start_c1_request(const fdl::Telegram& t, TimePoint now);
  void on_alarm_ack(AcyclicJob& job, const fdl::Telegram& t, TimePoint now);
  void protocol_violation(TimePoint now);
  bool poll_job(AcyclicJob& job, const fdl::Telegram& t);
  void run_acyclic(AcyclicJob& job, const AcyclicRequest& req, TimePoint now);
  static std::error_code finish_job(AcyclicJob& job, const AcyclicResult& r);
  static void fail_job(AcyclicJob& job, pdu::ErrorCode1 code_1);
  void close_dpv1();
  void on_c2_rm(const fdl::Telegram& t, TimePoint now);
  void on_c2_sap(const fdl::Telegram& t, TimePoint now);
  void start_c2_request(const fdl::Telegram& t, TimePoint now);
  void c2_close(C2Event why, TimePoint now);

  Config config_;
  SlaveApplication& app_;
  std::function<void(const Transition&)> trace_;
  Counters counters_;
  fdl::FcbResponder fcb_;
  fdl::Telegram tx_;       // the reply, when has_tx_ (the buffer is reused)
  bool has_tx_ = false;
  bool tx_taken_ = false;  // tx_ was handed out by next_transmit()

  // state and parameters
  State state_ = State::kWaitPrm;
  std::uint8_t address_;
  bool address_locked_;
  std::uint8_t master_ = 0xFF;
  std::uint8_t min_tsdr_;
  std::uint8_t group_ident_ = 0;
  bool wd_on_ = false;
  std::optional<Duration> wd_time_;
  std::optional<TimePoint> wd_deadline_;
  bool sync_req_ = false;
  bool freeze_req_ = false;
  std::optional<pdu::Dpv1Status> dpv1_;  // DPV1 mode from the accepted Set_Prm
                                         // ([IEC 61158-6-3 DPV1_Status])
  std::size_t input_length_ = 0;
  std::size_t output_length_ = 0;
  bool c1_open_ = false;

  // Global_Control ([IEC 61158-6-3 Global_Control])
  bool sync_mode_ = false;
  bool freeze_mode_ = false;
  fdl::DataUnit outputs_;  // last outputs received (Rd_Outp)
  fdl::DataUnit frozen_inputs_;
  bool held_outputs_valid_ = false;

  // diagnosis ([IEC 61158-6-3 Slave_Diag])
  bool prm_fault_ = false;
  bool cfg_fault_ = false;
  bool not_supported_ = false;
  bool ext_diag_ = false;
  bool stat_diag_ = false;
  bool diag_flag_ = false;
  boost::container::static_vector<std::uint8_t, 238> device_diag_;
  std::optional<Alarm> alarm_in_diag_;

  AlarmQueue alarms_;
  AcyclicJob c1_;
  AcyclicJob alarm_sap_;  // SAP 50 (extra alarm SAP)
  C2Connection c2_;
};

}  // namespace rs4sim::dp::slave
