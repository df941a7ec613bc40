// dp::Slave: address filter, FCB rule, SAP dispatch, transitions, timers, replies.
// Services are in slave_dpv0.cpp ([IEC 61158-6-3 DP-V0 services]), slave_dpv1.cpp
// ([IEC 61158-6-3 MSAC_C1, MSAC_C1 polling, DPV1 alarms, status PDUs]), slave_c2.cpp
// ([IEC 61158-6-3 MSAC_C2]).
#include "dp/slave/slave.h"

#include "dp/pdu/sap.h"
#include "dp/slave/slave_error.h"

#include <algorithm>
#include <stdexcept>
#include <system_error>

namespace rs4sim::dp::slave {

using fdl::FrameType;
using fdl::RequestFunction;
using fdl::ResponseStatus;

const char* to_string(State s) {
  switch (s) {
    case State::kWaitPrm: return "Wait_Prm";
    case State::kWaitCfg: return "Wait_Cfg";
    case State::kDataExch: return "Data_Exch";
  }
  return "?";
}

const char* to_string(TransitionReason r) {
  switch (r) {
    case TransitionReason::kPrmAccepted: return "Set_Prm accepted";
    case TransitionReason::kPrmFault: return "Prm_Fault";
    case TransitionReason::kNotSupported: return "Not_Supported";
    case TransitionReason::kCfgAccepted: return "Chk_Cfg accepted";
    case TransitionReason::kCfgFault: return "Cfg_Fault";
    case TransitionReason::kUnlock: return "Unlock_Req";
    case TransitionReason::kWatchdog: return "watchdog expired";
    case TransitionReason::kProtocolViolation: return "DPV1 protocol violation";
    case TransitionReason::kAddressChanged: return "Set_Slave_Add";
  }
  return "?";
}

AcyclicResult AcyclicResult::ok(std::span<const std::uint8_t> bytes) {
  if (bytes.size() > kMaxAcyclicData) {
    throw std::system_error(make_error_code(SlaveError::kResponseTooLong));
  }
  AcyclicResult r;
  r.kind = Kind::kData;
  r.data.assign(bytes.begin(), bytes.end());
  return r;
}

namespace {
const Config& checked(const Config& c) {
  if (const auto ec = c.validate()) throw std::system_error(ec, "dp::SlaveConfig");
  return c;
}
bool is_sdn(RequestFunction f) {
  return f == RequestFunction::kSdnLow || f == RequestFunction::kSdnHigh;
}
bool is_srd(RequestFunction f) {
  return f == RequestFunction::kSrdLow || f == RequestFunction::kSrdHigh;
}
bool is_sda(RequestFunction f) {
  return f == RequestFunction::kSdaLow || f == RequestFunction::kSdaHigh;
}
}  // namespace

Slave::Slave(const Config& config, SlaveApplication& app)
    : config_(checked(config)),
      app_(app),
      address_(config.address),
      address_locked_(config.address_change_locked),
      min_tsdr_(config.min_tsdr_default),
      alarms_(config.alarm_capacity, config.alarm_sequence_numbers, config.alarm_queue_capacity) {
  app_.on_attach(*this);
}

void Slave::restart(std::uint8_t address) {
  Config c = config_;
  c.address = address;
  config_ = checked(c);
  counters_ = Counters{};
  fcb_ = fdl::FcbResponder{};
  has_tx_ = false;
  tx_taken_ = false;
  state_ = State::kWaitPrm;
  address_ = address;
  address_locked_ = config_.address_change_locked;
  master_ = 0xFF;
  min_tsdr_ = config_.min_tsdr_default;
  group_ident_ = 0;
  wd_on_ = false;
  wd_time_.reset();
  wd_deadline_.reset();
  sync_req_ = false;
  freeze_req_ = false;
  dpv1_.reset();
  input_length_ = 0;
  output_length_ = 0;
  c1_open_ = false;
  sync_mode_ = false;
  freeze_mode_ = false;
  outputs_ = {};
  frozen_inputs_ = {};
  held_outputs_valid_ = false;
  prm_fault_ = false;
  cfg_fault_ = false;
  not_supported_ = false;
  ext_diag_ = false;
  stat_diag_ = false;
  diag_flag_ = false;
  device_diag_.clear();
  alarm_in_diag_.reset();
  alarms_ = AlarmQueue(config_.alarm_capacity, config_.alarm_sequence_numbers,
                       config_.alarm_queue_capacity);
  c1_ = AcyclicJob{};
  alarm_sap_ = AcyclicJob{};
  c2_ = C2Connection{};
}

// ---- Station ---------------------------------------------------------------------------

void Slave::on_telegram(const fdl::Telegram& t, TimePoint now) {
  ++counters_.telegrams_seen;
  check_timers(now);
  if (t.type == FrameType::kToken || t.type == FrameType::kShortAck || !t.fc.is_request()) {
    ++counters_.ignored;  // slaves ignore tokens and other stations' replies
                          // ([IEC 61158-4-3 token])
    return;
  }
  if (t.da == fdl::kBroadcastAddress) {
    // [IEC 61158-4-3 frame reception]: never answer DA 127; only SDN Global_Control is meaningful
    // ([IEC 61158-6-3 Global_Control]).
    if (is_sdn(t.fc.function()) && t.dsap == pdu::sap::kGlobalControl && t.ssap) {
      ++counters_.broadcasts;
      ++counters_.per_sap[pdu::sap::kGlobalControl];
      if (is_owner(t.sa)) retrigger_watchdog(t.sa, now);
      on_global_control(t, now);
    } else {
      ++counters_.ignored;
    }
    has_tx_ = false;
    return;
  }
  if (t.da != address_) {
    ++counters_.for_other_stations;
    return;
  }
  handle_request(t, now);
}

void Slave::handle_request(const fdl::Telegram& t, TimePoint now) {
  const RequestFunction f = t.fc.function();
  retrigger_watchdog(t.sa, now);
  has_tx_ = false;
  if (f == RequestFunction::kFdlStatus) {  // [docs/references.md#dp-worked-example]: reply SD1 FC
                                           // 00 (slave, OK)
    reply_status(t, ResponseStatus::kOk);
    return;
  }
  if (f == RequestFunction::kIdent || f == RequestFunction::kLsapStatus) {
    reply_rs(t);  // DECISION: FDL services a DP slave does not offer → RS
    return;
  }
  if (!is_sdn(f) && !is_srd(f) && !is_sda(f)) {
    ++counters_.ignored;  // TE/CV/MSRD: not for a DP slave
    return;
  }
  fdl::FcbVerdict verdict = fdl::FcbVerdict::kNotEvaluated;
  if (!is_sdn(f)) {
    verdict = fcb_.on_request(t.sa, t.fc);
    if (verdict == fdl::FcbVerdict::kRepeat && fcb_.stored_reply() != nullptr) {
      ++counters_.repeats_answered;  // [IEC 61158-4-3 FCB/FCV]: resend, do not execute again
      new_reply() = *fcb_.stored_reply();
      return;
    }
  }
  dispatch(t, now);
  if (is_sdn(f)) {
    has_tx_ = false;  // [IEC 61158-4-3 frame reception]: never reply to SDN
    return;
  }
  if (!has_tx_) return;
  if (tx_.type == FrameType::kSd2 && !tx_.dsap && tx_.data.empty()) tx_.type = FrameType::kSd1;
  if (is_sda(f) && tx_.type != FrameType::kShortAck &&
      tx_.fc.status() != ResponseStatus::kSapNotEnabled) {
    reply_short_ack();  // SDA is only acknowledged ([IEC 61158-4-3 short acknowledgement])
  }
  if (verdict != fdl::FcbVerdict::kNotEvaluated) fcb_.store_reply(tx_);
}

void Slave::dispatch(const fdl::Telegram& t, TimePoint now) {
  if (!t.dsap) {
    ++counters_.default_sap;
    on_data_exchange(t, now);
    return;
  }
  const std::uint8_t dsap = *t.dsap & 0x3F;
  ++counters_.per_sap[dsap];
  if (!t.ssap) {
    reply_rs(t);
    return;
  }
  if (dsap >= pdu::sap::kSetSlaveAdd && dsap <= pdu::sap::kChkCfg) {
    dispatch_dp_sap(t, now);
  } else if (dsap == pdu::sap::kMsacC1 || dsap == pdu::sap::kAlarm) {
    on_msac_c1(t, now);
  } else if (dsap == pdu::sap::kMsacC2Rm) {
    on_c2_rm(t, now);
  } else if (config_.c2_supported && dsap == config_.c2_sap) {
    on_c2_sap(t, now);
  } else {
    reply_rs(t);  // Ext_User_Prm (53) and unused SAPs are not activated
  }
}

void Slave::dispatch_dp_sap(const fdl::Telegram& t, TimePoint now) {
  if (*t.ssap != pdu::sap::kMasterMs0) {  // DP services come from master SAP 62
                                          // ([IEC 61158-6-3 SAP assignment])
    reply_rs(t);
    return;
  }
  switch (*t.dsap) {
    case pdu::sap::kSetSlaveAdd: on_set_slave_add(t, now); break;
    case pdu::sap::kRdInp: on_read_io(t, true, now); break;
    case pdu::sap::kRdOutp: on_read_io(t, false, now); break;
    case pdu::sap::kGlobalControl:
      on_global_control(t, now);
      reply_short_ack();
      break;
    case pdu::sap::kGetCfg: on_get_cfg(t); break;
    case pdu::sap::kSlaveDiag: on_slave_diag(t); break;
    case pdu::sap::kSetPrm: on_set_prm(t, now); break;
    default: on_chk_cfg(t, now); break;
  }
}

void Slave::on_time(TimePoint now) {
  check_timers(now);
  const auto app_deadline = app_.next_deadline();
  if (app_deadline && now >= *app_deadline) app_.on_time(now);
}

std::optional<TimePoint> Slave::next_deadline() const {
  std::optional<TimePoint> d = wd_deadline_;
  const auto fold = [&d](std::optional<TimePoint> t) {
    if (t && (!d || *t < *d)) d = t;
  };
  if (c2_.bound) fold(c2_.deadline);
  fold(app_.next_deadline());
  return d;
}

void Slave::on_malformed_frame(std::error_code why) {
  (void)why;  // the link's decoder keeps the per-kind statistics
  ++counters_.malformed_dropped;
}

std::optional<fdl::Telegram> Slave::take_transmit() {
  if (!has_tx_ || tx_taken_) return std::nullopt;  // the link's second call after each reply
  has_tx_ = false;
  return std::move(tx_);
}

const fdl::Telegram* Slave::next_transmit(fdl::Telegram& /*scratch*/) {
  if (!has_tx_ || tx_taken_) return nullptr;  // the link's second call after each reply
  tx_taken_ = true;
  return &tx_;
}

// ---- timers and transitions ------------------------------------------------------------

void Slave::check_timers(TimePoint now) {
  if (wd_deadline_ && now >= *wd_deadline_) {  // [IEC 61158-6-3 watchdog]: expiry at exactly T_WD
    ++counters_.watchdog_expiries;
    reset_parameters(false);
    enter(State::kWaitPrm, TransitionReason::kWatchdog, now);
  }
  // [IEC 61158-6-3 MSAC_C2] step 5
  if (c2_.bound && now >= c2_.deadline) c2_close(C2Event::kTimedOut, now);
}

void Slave::retrigger_watchdog(std::uint8_t sa, TimePoint now) {
  if (wd_deadline_ && wd_time_ && sa == master_) wd_deadline_ = now + *wd_time_;
}

void Slave::reset_parameters(bool keep_master) {
  if (!keep_master) master_ = pdu::sap::kNoMasterAddress;
  wd_on_ = false;
  wd_time_.reset();
  wd_deadline_.reset();
  group_ident_ = 0;
  sync_req_ = false;
  freeze_req_ = false;
  dpv1_.reset();
  input_length_ = 0;
  output_length_ = 0;
}

void Slave::enter(State to, TransitionReason why, TimePoint now) {
  const State from = state_;
  if (from == State::kDataExch && to != State::kDataExch) {
    // [IEC 61158-6-3 slave state machine]: leaving Data_Exch puts the outputs into the safe state;
    // [IEC 61158-6-3 MSAC_C1] closes C1/alarms.
    sync_mode_ = false;
    freeze_mode_ = false;
    held_outputs_valid_ = false;
    std::fill(outputs_.begin(), outputs_.end(), std::uint8_t{0});
    app_.on_outputs_cleared(OutputClear::kLeftDataExchange, now);
  }
  if (to != State::kDataExch) close_dpv1();
  state_ = to;
  if (to == State::kDataExch && from != State::kDataExch && dpv1_ && dpv1_->any_alarm_enabled()) {
    alarms_.open(*dpv1_);  // [IEC 61158-6-3 MSAC_C1]: alarm machine opens on entering Data_Exch
  }
  const Transition tr{from, to, why, now};
  if (trace_) trace_(tr);
  app_.on_state_change(from, to, why, now);
}

// ---- replies -----------------------------------------------------------------------------

fdl::Telegram& Slave::new_reply() {
  // As a fresh fdl::Telegram{}, field by field: the buffer is reused, not zero-filled again.
  tx_taken_ = false;
  has_tx_ = true;
  tx_.type = FrameType::kSd2;
  tx_.da = 0;
  tx_.sa = 0;
  tx_.fc = {};
  tx_.dsap.reset();
  tx_.ssap.reset();
  tx_.data.clear();
  return tx_;
}

void Slave::reply_short_ack() { new_reply().type = FrameType::kShortAck; }

void Slave::reply_status(const fdl::Telegram& req, ResponseStatus st) {
  new_reply();
  tx_.type = FrameType::kSd1;
  tx_.da = req.sa;
  tx_.sa = address_;
  tx_.fc = fdl::FrameControl::response(st);
}

void Slave::reply_rs(const fdl::Telegram& req) {
  ++counters_.rs_replies;
  reply_status(req, ResponseStatus::kSapNotEnabled);
}

fdl::DataUnit& Slave::reply_data(const fdl::Telegram& req, ResponseStatus st) {
  reply_status(req, st);
  tx_.type = FrameType::kSd2;
  tx_.dsap = req.ssap;  // reply frames swap the SAPs ([IEC 61158-6-3 SAP assignment])
  tx_.ssap = req.dsap;
  return tx_.data;
}

}  // namespace rs4sim::dp::slave
