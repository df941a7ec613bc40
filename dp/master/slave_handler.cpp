#include "dp/master/slave_handler.h"

#include "dp/master/master_error.h"
#include "dp/pdu/sap.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace rs4sim::dp::master {

const char* to_string(PollState s) {
  switch (s) {
    case PollState::kStatusRequest: return "StatusRequest";
    case PollState::kReadDiag: return "ReadDiag";
    case PollState::kSetPrm: return "SetPrm";
    case PollState::kChkCfg: return "ChkCfg";
    case PollState::kWaitReady: return "WaitReady";
    case PollState::kDataExchange: return "DataExchange";
  }
  return "?";
}

SlaveHandler::SlaveHandler(const SlaveEntry& config, bool fdl_status_first)
    : config_(config),
      fdl_status_first_(fdl_status_first),
      state_(fdl_status_first ? PollState::kStatusRequest : PollState::kReadDiag),
      dpv1_(config.address, config.c1_response_timeout),
      alarms_(config.address, config.prm.dpv1 ? config.prm.dpv1->alarm_mode : 0) {
  (void)pdu::encode_set_prm(config_.prm, prm_du_);  // validated by validate(SlaveEntry)
  outputs_.resize(config_.output_length, 0);
}

PollState SlaveHandler::initial_state() const {
  return fdl_status_first_ ? PollState::kStatusRequest : PollState::kReadDiag;
}

std::uint8_t SlaveHandler::alarm_dsap() const {
  return config_.extra_alarm_sap ? pdu::sap::kAlarm : pdu::sap::kMsacC1;
}

bool SlaveHandler::make(Request& out, SlaveContext& ctx, RequestKind kind, fdl::FrameControl fc,
                        std::optional<std::uint8_t> dsap, std::span<const std::uint8_t> data,
                        std::size_t max_reply) const {
  // Built in place, in the slot the master keeps it in (fdl::make_data_telegram's rules).
  if (data.size() > fdl::kMaxDataUnit) throw std::invalid_argument("fdl: DU longer than 246 bytes");
  fdl::Telegram& t = out.telegram;
  t.da = config_.address;
  t.sa = ctx.master_address;
  t.fc = fc;
  // DP services: master SSAP 62 (MS0), DPV1 C1: 51 ([IEC 61158-6-3 SAP assignment]); DSAP and SSAP
  // go together.
  if (dsap) {
    const bool c1 = kind == RequestKind::kDpv1 || kind == RequestKind::kAlarmAck;
    t.dsap = *dsap;
    t.ssap = c1 ? pdu::sap::kMasterMsac1 : pdu::sap::kMasterMs0;
  } else {
    t.dsap.reset();
    t.ssap.reset();
  }
  t.data.resize(data.size(), boost::container::default_init);
  if (!data.empty()) std::memcpy(t.data.data(), data.data(), data.size());
  t.type = (data.empty() && !dsap) ? fdl::FrameType::kSd1 : fdl::FrameType::kSd2;
  out.kind = kind;
  out.max_reply_bytes = max_reply;
  return true;
}

bool SlaveHandler::next_request(SlaveContext& ctx, TimePoint now, Request& out) {
  if (turn_.count >= kMaxRequestsPerTurn) return false;
  const bool startup = state_ != PollState::kDataExchange;
  if (startup) {
    if (turn_.count > 0 && !continue_) return false;
    continue_ = false;
    if (state_ == PollState::kWaitReady && now - wait_ready_since_ >= ctx.ready_timeout) {
      restart(ctx, make_error_code(MasterError::kStartupTimeout), PollState::kReadDiag);
    }
  }
  // Built straight into `out` (no copy of the telegram).
  const bool r = startup ? startup_request(ctx, out) : cyclic_request(ctx, now, out);
  if (r) {
    ++turn_.count;
    ++counters_.requests;
    last_kind_ = out.kind;
  }
  return r;
}

bool SlaveHandler::startup_request(SlaveContext& ctx, Request& out) {
  namespace sap = pdu::sap;
  const std::uint8_t addr = config_.address;
  using F = fdl::RequestFunction;
  switch (state_) {
    case PollState::kStatusRequest:  // `10 DA SA 49 FCS 16`, no FCB ([IEC 61158-4-3 FCB/FCV]
                                     // [IEC 61158-6-3 master start-up of a slave]
                                     // [pyprofibus dp_master.py] step 0)
      return make(out, ctx, RequestKind::kFdlStatus, fdl::FcbInitiator::unsequenced(F::kFdlStatus),
                  std::nullopt, {}, 6);
    case PollState::kReadDiag:
    case PollState::kWaitReady:
      return make(out, ctx, RequestKind::kDiag, ctx.fcb.next(addr, F::kSrdHigh), sap::kSlaveDiag, {},
                  fdl::kMaxTelegramSize);
    case PollState::kSetPrm:
      return make(out, ctx, RequestKind::kSetPrm, ctx.fcb.next(addr, F::kSrdHigh), sap::kSetPrm,
                  bytes(prm_du_), 6);
    case PollState::kChkCfg:
      return make(out, ctx, RequestKind::kChkCfg, ctx.fcb.next(addr, F::kSrdHigh), sap::kChkCfg,
                  bytes(config_.cfg), 6);
    case PollState::kDataExchange: break;
  }
  return false;
}

bool SlaveHandler::data_exchange_request(SlaveContext& ctx, Request& out) const {
  // [IEC 61158-6-3 Data_Exchange]: SRD_HI on the default SAP with the whole output image; in CLEAR
  // zeros, or an empty telegram for slaves parameterised with Fail_Safe.
  // The output image goes straight into the telegram (no intermediate copy).
  fdl::DataUnit zeros;
  std::span<const std::uint8_t> image = bytes(outputs_);
  if (ctx.clear_mode) {
    if (!config_.fail_safe()) zeros.resize(outputs_.size(), 0);
    image = bytes(zeros);
  }
  const std::size_t reply = std::max<std::size_t>(6, 9 + config_.input_length);
  return make(out, ctx, RequestKind::kDataExchange,
              ctx.fcb.next(config_.address, fdl::RequestFunction::kSrdHigh), std::nullopt, image,
              reply);
}

bool SlaveHandler::cyclic_request(SlaveContext& ctx, TimePoint now, Request& out) {
  using F = fdl::RequestFunction;
  if (!turn_.dx) {
    turn_.dx = true;
    return data_exchange_request(ctx, out);
  }
  if (diag_needed_ && !turn_.diag) {  // DH → Slave_Diag in the next slot
                                      // ([IEC 61158-6-3 class 1 master cycle])
    turn_.diag = true;
    return make(out, ctx, RequestKind::kDiag, ctx.fcb.next(config_.address, F::kSrdHigh),
                pdu::sap::kSlaveDiag, {}, fdl::kMaxTelegramSize);
  }
  if (!turn_.alarm && (config_.extra_alarm_sap || !dpv1_.busy())) {
    turn_.alarm = true;
    if (auto ack = alarms_.next_ack()) {
      fdl::DataUnit du;
      (void)pdu::encode(*ack, du);
      return make(out, ctx, RequestKind::kAlarmAck, ctx.fcb.next(config_.address, F::kSrdLow),
                  alarm_dsap(), bytes(du), fdl::kMaxTelegramSize);
    }
  }
  if (!turn_.dpv1) {
    turn_.dpv1 = true;
    dpv1_.check_timeout(now, ctx.events);
    if (auto du = dpv1_.next_pdu(now)) {
      return make(out, ctx, RequestKind::kDpv1, ctx.fcb.next(config_.address, F::kSrdLow),
                  pdu::sap::kMsacC1, bytes(*du), fdl::kMaxTelegramSize);
    }
  }
  return false;
}

void SlaveHandler::on_cycle_start(SlaveContext& ctx, TimePoint now) {
  dpv1_.check_timeout(now, ctx.events);
}

std::error_code SlaveHandler::set_outputs(std::span<const std::uint8_t> outputs) {
  if (outputs.size() != config_.output_length) {
    return make_error_code(MasterError::kOutputLengthMismatch);
  }
  std::copy(outputs.begin(), outputs.end(), outputs_.begin());
  return {};
}

std::span<const std::uint8_t> SlaveHandler::inputs() const {
  if (state_ != PollState::kDataExchange) return {};
  return {inputs_.data(), inputs_.size()};
}

std::error_code SlaveHandler::submit(Dpv1Job job) {
  if (state_ != PollState::kDataExchange) return make_error_code(MasterError::kNotInDataExchange);
  if (!config_.dpv1_enabled()) return make_error_code(MasterError::kDpv1NotEnabled);
  return dpv1_.submit(std::move(job));
}

std::error_code SlaveHandler::acknowledge_alarm(std::uint8_t slot, std::uint8_t type,
                                                std::uint8_t seq_nr) {
  return alarms_.acknowledge(slot, type, seq_nr);
}

SlaveStatus SlaveHandler::status() const {
  SlaveStatus s;
  s.address = config_.address;
  s.state = state_;
  s.state_name = to_string(state_);
  s.counters = counters_;
  s.last_diag = last_diag_;
  s.last_error = last_error_;
  s.alarms_outstanding = alarms_.outstanding();
  s.dpv1_queued = dpv1_.queued();
  return s;
}

}  // namespace rs4sim::dp::master
