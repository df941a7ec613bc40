// Reply evaluation and state transitions of SlaveHandler
// ([IEC 61158-6-3 master start-up of a slave, class 1 master cycle, slave supervision]
// [pyprofibus dp_master.py]).

#include "dp/master/master_error.h"
#include "dp/master/slave_handler.h"
#include "dp/pdu/sap.h"

#include <algorithm>

namespace rs4sim::dp::master {
namespace {

using S = fdl::ResponseStatus;

// Error for a reply that is neither the expected answer nor a data-less positive ack.
std::error_code negative_reply(const Reply& r) {
  if (!r.short_ack && r.status == S::kSapNotEnabled)
    return make_error_code(MasterError::kSapNotEnabled);
  if (!r.short_ack && (r.status == S::kUserError || r.status == S::kNoResource)) {
    return make_error_code(MasterError::kServiceRejected);
  }
  return make_error_code(MasterError::kInvalidResponse);
}

// A reply with status RS, RR or UE ([IEC 61158-4-3 frame control, response status]).
bool negative_status(const Reply& r) {
  return !r.short_ack && (r.status == S::kSapNotEnabled || r.status == S::kNoResource ||
                          r.status == S::kUserError);
}

// A reply that does not fit its request counts as Illegal, unless it is a negative reply,
// which counts as RS/RR only: ProfiTrace's live list counts the two apart.
void count_unfitting(PollCounters& c, const Reply& r) {
  if (!negative_status(r)) ++c.invalid_responses;
}

}  // namespace

void SlaveHandler::on_reply(SlaveContext& ctx, const Reply& r, TimePoint now) {
  if (negative_status(r)) ++counters_.negative_replies;
  switch (last_kind_) {
    case RequestKind::kFdlStatus: on_status_reply(ctx, r); break;
    case RequestKind::kDiag: on_diag_reply(ctx, r); break;
    case RequestKind::kSetPrm:
    case RequestKind::kChkCfg: on_prm_cfg_reply(ctx, r, now); break;
    case RequestKind::kDataExchange: on_dx_reply(ctx, r); break;
    case RequestKind::kDpv1: dpv1_.on_reply(r, ctx.events); break;
    case RequestKind::kAlarmAck: alarms_.on_ack_reply(r, alarm_dsap(), ctx.events); break;
  }
}

void SlaveHandler::on_no_answer(SlaveContext& ctx) {
  // [IEC 61158-6-3 slave supervision]: mark the slave offline, restart at step 0/1 with a fresh FCB
  // (FCV=0).
  ++counters_.no_answer;
  const auto no_answer = make_error_code(MasterError::kNoAnswer);
  if (last_kind_ == RequestKind::kDpv1) {
    dpv1_.abort_all(no_answer, make_error_code(MasterError::kAborted), ctx.events);
  }
  ctx.fcb.responder_lost(config_.address);
  restart(ctx, no_answer, initial_state());
}

void SlaveHandler::on_status_reply(SlaveContext& ctx, const Reply& r) {
  // [IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py] step 0: SD1 reply, FC
  // status OK with station type "slave" (`00`).
  if (r.short_ack || r.has_saps || !r.data.empty() || r.status != S::kOk) {
    count_unfitting(counters_, r);
    fault(ctx, make_error_code(MasterError::kInvalidResponse));
    return;
  }
  if (r.station_type != fdl::StationType::kSlave) {
    fault(ctx, make_error_code(MasterError::kNotASlave));
    return;
  }
  state_ = PollState::kReadDiag;
  continue_ = true;
}

void SlaveHandler::on_diag_reply(SlaveContext& ctx, const Reply& r) {
  // Slave_Diag reply: DL/DH with DSAP 62 (master MS0) and SSAP 60
  // ([IEC 61158-6-3 SAP assignment, Slave_Diag]).
  const bool shaped = r.carries_data() && r.from_saps(pdu::sap::kMasterMs0, pdu::sap::kSlaveDiag);
  auto diag = shaped ? pdu::decode_slave_diag(r.data)
                     : pdu::Result<pdu::SlaveDiag>(make_error_code(pdu::PduError::kTooShort));
  if (!diag) {
    count_unfitting(counters_, r);
    restart(ctx, shaped ? make_error_code(MasterError::kInvalidResponse) : negative_reply(r),
            PollState::kReadDiag);
    return;
  }
  ++counters_.diag_reads;
  record_diag(ctx, r.data, state_ == PollState::kDataExchange);
  switch (state_) {
    case PollState::kReadDiag: on_first_diag(ctx, diag.value()); break;
    case PollState::kWaitReady: on_ready_diag(ctx, diag.value()); break;
    case PollState::kDataExchange: on_cyclic_diag(ctx, diag.value()); break;
    default: break;
  }
}

void SlaveHandler::on_first_diag(SlaveContext& ctx, const pdu::SlaveDiag& d) {
  // [IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py] step 1: the Ident must
  // match; Master_Add of another master ⇒ Master_Lock.
  if (d.ident_number != config_.prm.ident_number) {
    fault(ctx, make_error_code(MasterError::kIdentMismatch));
    return;
  }
  if (d.master_add != pdu::sap::kNoMasterAddress && d.master_add != ctx.master_address) {
    fault(ctx, make_error_code(MasterError::kMasterLock));
    return;
  }
  state_ = PollState::kSetPrm;
  continue_ = true;
}

void SlaveHandler::on_ready_diag(SlaveContext& ctx, const pdu::SlaveDiag& d) {
  // [IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py] step 4: faults restart at
  // step 1, Prm_Req at step 2; wait while not ready.
  const auto err = [](MasterError e) { return make_error_code(e); };
  if (d.ident_number != config_.prm.ident_number) {
    restart(ctx, err(MasterError::kIdentMismatch), PollState::kReadDiag);
  } else if (d.status1.prm_fault) {
    restart(ctx, err(MasterError::kPrmFault), PollState::kReadDiag);
  } else if (d.status1.cfg_fault) {
    restart(ctx, err(MasterError::kCfgFault), PollState::kReadDiag);
  } else if (d.status1.not_supported) {
    restart(ctx, err(MasterError::kNotSupported), PollState::kReadDiag);
  } else if (d.status2.prm_req) {
    state_ = PollState::kSetPrm;
  } else if (d.master_add != ctx.master_address) {
    restart(ctx, err(MasterError::kMasterLock), PollState::kReadDiag);
  } else if (!d.status1.station_not_ready && !d.status2.stat_diag) {
    enter_data_exchange(ctx);
    continue_ = true;  // first Data_Exchange in this turn
  }
}

void SlaveHandler::on_cyclic_diag(SlaveContext& ctx, const pdu::SlaveDiag& d) {
  if (config_.dpv1_enabled()) {
    if (auto ec =
            alarms_.on_diag({d.ext_diag.data(), d.ext_diag.size()}, ctx.auto_alarm_ack, ctx.events))
      fault(ctx, ec);
  }
  diag_needed_ = d.status2.stat_diag;  // keep fetching while Stat_Diag ([IEC 61158-6-3 Slave_Diag])
  const auto err = [](MasterError e) { return make_error_code(e); };
  if (d.status1.prm_fault || d.status1.cfg_fault || d.status1.not_supported) {
    leave_data_exchange(ctx,
                        err(d.status1.prm_fault   ? MasterError::kPrmFault
                            : d.status1.cfg_fault ? MasterError::kCfgFault
                                                  : MasterError::kNotSupported),
                        PollState::kReadDiag);
  } else if (d.status2.prm_req || d.status1.station_not_ready ||
             d.master_add != ctx.master_address) {
    // [IEC 61158-6-3 slave supervision]: slave reset or watchdog expiry ⇒ re-parameterise; another
    // master ⇒ step 1.
    const bool foreign =
        d.master_add != ctx.master_address && d.master_add != pdu::sap::kNoMasterAddress;
    leave_data_exchange(ctx, err(MasterError::kLeftDataExchange),
                        foreign ? PollState::kReadDiag : PollState::kSetPrm);
  }
}

void SlaveHandler::on_prm_cfg_reply(SlaveContext& ctx, const Reply& r, TimePoint now) {
  // Set_Prm/Chk_Cfg are confirmed by SC only; acceptance shows in the next diag
  // ([IEC 61158-4-3 short acknowledgement]).
  if (!r.empty_ack()) {
    count_unfitting(counters_, r);
    restart(ctx, negative_reply(r), PollState::kReadDiag);
    return;
  }
  if (state_ == PollState::kSetPrm) {
    state_ = PollState::kChkCfg;
  } else {
    state_ = PollState::kWaitReady;
    wait_ready_since_ = now;
  }
  continue_ = true;
}

void SlaveHandler::on_dx_reply(SlaveContext& ctx, const Reply& r) {
  // [IEC 61158-6-3 Data_Exchange]: DL/DH with the input image on the default SAP, or SC for a slave
  // without inputs; RS ⇒ the slave left DATA_EXCH ([IEC 61158-6-3 slave supervision]).
  std::span<const std::uint8_t> in;
  if (r.has_saps || !(r.carries_data() || r.empty_ack())) {
    count_unfitting(counters_, r);
    leave_data_exchange(ctx, negative_reply(r), PollState::kReadDiag);
    return;
  }
  if (r.carries_data()) in = r.data;
  if (in.size() != config_.input_length) {
    ++counters_.invalid_responses;
    leave_data_exchange(ctx, make_error_code(MasterError::kInputLengthMismatch),
                        PollState::kReadDiag);
    return;
  }
  std::copy(in.begin(), in.end(), inputs_.begin());
  ++counters_.data_exchanges;
  if (r.diag_pending()) diag_needed_ = true;
}

void SlaveHandler::record_diag(SlaveContext& ctx, std::span<const std::uint8_t> du,
                               bool always_report) {
  const bool changed = !std::equal(du.begin(), du.end(), last_diag_.begin(), last_diag_.end());
  if (changed) last_diag_.assign(du.begin(), du.end());
  if (changed || always_report) ctx.events.push(DiagReceived{config_.address, last_diag_});
}

void SlaveHandler::fault(SlaveContext& ctx, std::error_code reason) {
  last_error_ = reason;
  if (reason != reported_) {
    reported_ = reason;
    ctx.events.push(SlaveFault{config_.address, reason});
  }
}

void SlaveHandler::restart(SlaveContext& ctx, std::error_code reason, PollState next) {
  if (state_ == PollState::kDataExchange) {
    leave_data_exchange(ctx, reason, next);
    return;
  }
  state_ = next;
  continue_ = false;
  if (reason) fault(ctx, reason);
}

void SlaveHandler::enter_data_exchange(SlaveContext& ctx) {
  state_ = PollState::kDataExchange;
  reported_ = {};
  diag_needed_ = false;
  inputs_.assign(config_.input_length, 0);
  ++counters_.entered_data_exchange;
  ctx.events.push(SlaveEnteredDataExchange{config_.address});
}

void SlaveHandler::leave_data_exchange(SlaveContext& ctx, std::error_code reason, PollState next) {
  ++counters_.left_data_exchange;
  state_ = next;
  continue_ = false;
  diag_needed_ = false;
  dpv1_.abort_all(make_error_code(MasterError::kAborted), make_error_code(MasterError::kAborted),
                  ctx.events);
  alarms_.reset();
  ctx.events.push(SlaveLeftDataExchange{config_.address, reason});
  last_error_ = reason;  // reported by the event above, not again as SlaveFault
  reported_ = reason;
}

}  // namespace rs4sim::dp::master
