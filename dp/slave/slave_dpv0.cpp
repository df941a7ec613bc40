// dp::Slave DP-V0 services: Set_Prm ([IEC 61158-6-3 Set_Prm, DPV1_Status]), Chk_Cfg/Get_Cfg
// ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]), Global_Control ([IEC 61158-6-3 Global_Control]), Data_Exchange
// ([IEC 61158-6-3 Data_Exchange]), Rd_Inp/Rd_Outp and Set_Slave_Add
// ([IEC 61158-6-3 Set_Slave_Add, Rd_Inp/Rd_Outp]).
#include "dp/pdu/cfg.h"
#include "dp/pdu/global_control.h"
#include "dp/pdu/sap.h"
#include "dp/pdu/set_slave_add.h"
#include "dp/slave/slave.h"

#include <algorithm>
#include <chrono>

namespace rs4sim::dp::slave {

using fdl::ResponseStatus;

void Slave::fault_to_wait_prm(TransitionReason why, bool keep_master, TimePoint now) {
  reset_parameters(keep_master);
  enter(State::kWaitPrm, why, now);
}

// ---- Set_Prm (DSAP 61) ---------------------------------------------------------------------

void Slave::on_set_prm(const fdl::Telegram& t, TimePoint now) {
  // DECISION ([docs/decisions.md#dp-open-points] UNCERTAIN): a slave locked to another master does
  // not execute it.
  if (state_ != State::kWaitPrm && master_ != pdu::sap::kNoMasterAddress && !is_owner(t.sa)) {
    reply_rs(t);
    return;
  }
  reply_short_ack();  // SC only says "received"; acceptance shows in the diagnosis
                      // ([IEC 61158-4-3 short acknowledgement])
  const auto layout = config_.dpv1 ? pdu::PrmLayout::kDpv1 : pdu::PrmLayout::kDpv0;
  const auto decoded = pdu::decode_set_prm(bytes_of(t.data), layout);
  if (!decoded) {
    prm_fault_ = true;
    fault_to_wait_prm(TransitionReason::kPrmFault, false, now);
    return;
  }
  const pdu::SetPrm& prm = decoded.value();
  const auto& st = prm.station_status;
  if (st.unlock_req) {  // [IEC 61158-6-3 Set_Prm]: 01 and 11 release the slave for other masters
    prm_fault_ = cfg_fault_ = not_supported_ = false;
    fault_to_wait_prm(TransitionReason::kUnlock, false, now);
    return;
  }
  if (!st.lock_req) {  // [IEC 61158-6-3 Set_Prm]: 00 = only min TSDR is taken over
    if (prm.min_tsdr != 0) min_tsdr_ = prm.min_tsdr;
    return;
  }
  prm_fault_ = cfg_fault_ = not_supported_ = false;
  switch (judge_prm(prm, now)) {
    case PrmVerdict::kAccept: take_over_prm(prm, t.sa, now); break;
    case PrmVerdict::kPrmFault:
      prm_fault_ = true;
      fault_to_wait_prm(TransitionReason::kPrmFault, false, now);
      break;
    case PrmVerdict::kNotSupported:
      not_supported_ = true;
      fault_to_wait_prm(TransitionReason::kNotSupported, false, now);
      break;
  }
}

PrmVerdict Slave::judge_prm(const pdu::SetPrm& prm, TimePoint now) {
  const auto& st = prm.station_status;
  // [IEC 61158-6-3 Set_Prm]
  if (prm.ident_number != config_.ident_number) return PrmVerdict::kPrmFault;
  if (st.wd_on && (prm.wd_fact_1 == 0 || prm.wd_fact_2 == 0)) return PrmVerdict::kPrmFault;
  if ((st.sync_req && !config_.sync_supported) || (st.freeze_req && !config_.freeze_supported)) {
    return PrmVerdict::kNotSupported;  // [IEC 61158-6-3 Set_Prm] Not_Supported
  }
  if (prm.dpv1 && prm.dpv1->dpv1_enable) {  // [IEC 61158-6-3 DPV1_Status]
    const auto& d = *prm.dpv1;
    if (d.publisher_enable || d.isom_req || d.prm_cmd) return PrmVerdict::kNotSupported;
    if (d.fail_safe && !config_.fail_safe_supported) return PrmVerdict::kNotSupported;
    if (d.wd_base_1ms && !config_.wd_base_1ms_supported) return PrmVerdict::kNotSupported;
  }
  return app_.check_parameters(prm, now);
}

void Slave::take_over_prm(const pdu::SetPrm& prm, std::uint8_t master, TimePoint now) {
  using std::chrono::milliseconds;
  master_ = master;
  wd_on_ = prm.station_status.wd_on;
  const bool base_1ms = prm.dpv1 && prm.dpv1->dpv1_enable && prm.dpv1->wd_base_1ms;
  if (wd_on_) {  // [IEC 61158-6-3 Set_Prm]: T_WD = base · WD_Fact_1 · WD_Fact_2
    wd_time_ = milliseconds(base_1ms ? 1 : 10) * prm.wd_fact_1 * prm.wd_fact_2;
    wd_deadline_ = now + *wd_time_;
  } else {
    wd_time_.reset();
    wd_deadline_.reset();
  }
  if (prm.min_tsdr != 0) min_tsdr_ = prm.min_tsdr;
  group_ident_ = prm.group_ident;
  sync_req_ = prm.station_status.sync_req;
  freeze_req_ = prm.station_status.freeze_req;
  if (prm.dpv1 && prm.dpv1->dpv1_enable) {
    dpv1_ = prm.dpv1;
  } else {
    dpv1_.reset();
  }
  enter(State::kWaitCfg, TransitionReason::kPrmAccepted, now);
}

// ---- Chk_Cfg (DSAP 62) / Get_Cfg (DSAP 59) ---------------------------------------------------

void Slave::on_chk_cfg(const fdl::Telegram& t, TimePoint now) {
  if (state_ == State::kWaitPrm || !is_owner(t.sa)) {
    reply_rs(t);
    return;
  }
  reply_short_ack();
  const auto summary = pdu::summarize_cfg(bytes_of(t.data), pdu::CfgService::kChkCfg);
  const bool user_check = dpv1_ && dpv1_->check_cfg_mode;
  const CfgVerdict verdict =
      summary ? app_.check_config(bytes_of(t.data), user_check, now) : CfgVerdict::kCfgFault;
  if (verdict != CfgVerdict::kAccept) {
    cfg_fault_ = true;  // DECISION: Cfg_Fault → Wait_Prm, Master_Add kept for the master
    fault_to_wait_prm(TransitionReason::kCfgFault, true, now);
    return;
  }
  cfg_fault_ = false;
  input_length_ = summary.value().input_bytes;
  output_length_ = summary.value().output_bytes;
  outputs_.assign(output_length_, 0);
  c1_open_ = dpv1_.has_value();  // [IEC 61158-6-3 MSAC_C1]: SAP 51 opens when Chk_Cfg is accepted
  if (state_ != State::kDataExch) {
    enter(State::kDataExch, TransitionReason::kCfgAccepted, now);
  }
}

void Slave::on_get_cfg(const fdl::Telegram& t) {
  const auto cfg = app_.real_config();
  fdl::DataUnit& du = reply_data(t, ResponseStatus::kDataLow);
  const std::size_t n = std::min(cfg.size(), fdl::kMaxDataUnit - 2);
  du.assign(cfg.begin(), cfg.begin() + static_cast<std::ptrdiff_t>(n));
}

// ---- Global_Control (DSAP 58) ----------------------------------------------------------------

void Slave::on_global_control(const fdl::Telegram& t, TimePoint now) {
  // Executed only in Data_Exch, from the owning master, for a selected group
  // ([IEC 61158-6-3 Global_Control]).
  if (state_ != State::kDataExch || !is_owner(t.sa)) return;
  const auto decoded = pdu::decode_global_control(bytes_of(t.data));
  if (!decoded || !decoded.value().addresses(group_ident_)) return;
  const pdu::GlobalControl& gc = decoded.value();
  if (gc.clear_data) {
    std::fill(outputs_.begin(), outputs_.end(), std::uint8_t{0});
    app_.on_outputs_cleared(OutputClear::kGlobalControlClear, now);
  }
  if (((gc.sync || gc.unsync) && !sync_req_) || ((gc.freeze || gc.unfreeze) && !freeze_req_)) {
    not_supported_ = true;  // not requested in Set_Prm ([IEC 61158-6-3 Global_Control])
    diag_flag_ = true;
    return;
  }
  if (gc.unsync || gc.sync) {  // DECISION: Unsync wins over Sync in the same command
    // Sync applies the last outputs now and holds later ones until the next Sync.
    sync_mode_ = !gc.unsync;
    if (held_outputs_valid_) app_.on_outputs(bytes_of(outputs_), now);
    held_outputs_valid_ = false;
  }
  if (gc.unfreeze) {
    freeze_mode_ = false;
  } else if (gc.freeze) {
    freeze_mode_ = false;
    fill_inputs(frozen_inputs_, now);  // latch the live inputs
    freeze_mode_ = true;
  }
}

// ---- Data_Exchange (default SAP) -------------------------------------------------------------

void Slave::fill_inputs(fdl::DataUnit& out, TimePoint now) {
  if (freeze_mode_) {
    out.assign(frozen_inputs_.begin(), frozen_inputs_.end());
    return;
  }
  out.resize(input_length_);
  app_.read_inputs(std::span<std::uint8_t>(out.data(), out.size()), now);
}

void Slave::on_data_exchange(const fdl::Telegram& t, TimePoint now) {
  if (state_ != State::kDataExch || !is_owner(t.sa)) {
    reply_rs(t);  // [IEC 61158-6-3 slave state machine]: DX outside Data_Exch → SD1 FC RS
    return;
  }
  if (t.data.empty() && output_length_ > 0 && dpv1_ && dpv1_->fail_safe) {
    std::fill(outputs_.begin(), outputs_.end(), std::uint8_t{0});  // [IEC 61158-6-3 Data_Exchange]
                                                                   // Fail_Safe
    app_.on_outputs_cleared(OutputClear::kFailSafe, now);
  } else if (t.data.size() != output_length_) {
    ++counters_.output_length_errors;  // DECISION ([docs/decisions.md#dp-open-points] UNCERTAIN):
                                       // keep last outputs
  } else {
    outputs_.assign(t.data.begin(), t.data.end());
    if (sync_mode_) {
      held_outputs_valid_ = true;
    } else {
      app_.on_outputs(bytes_of(outputs_), now);
    }
  }
  const auto status = diag_flag() ? ResponseStatus::kDataHigh : ResponseStatus::kDataLow;
  if (input_length_ == 0 && !freeze_mode_) {
    if (diag_flag()) {
      reply_status(t, status);  // [IEC 61158-6-3 Data_Exchange]: SD1 DH flags the diagnosis
    } else {
      reply_short_ack();  // [IEC 61158-6-3 Data_Exchange]: slave without inputs answers SC
    }
    return;
  }
  fill_inputs(reply_data(t, status), now);
}

// ---- Rd_Inp (56) / Rd_Outp (57) / Set_Slave_Add (55) ----------------------------------------

void Slave::on_read_io(const fdl::Telegram& t, bool inputs, TimePoint now) {
  if (state_ != State::kDataExch) {
    reply_rs(t);  // DECISION ([docs/decisions.md#dp-open-points] UNCERTAIN): only in Data_Exch,
                  // from any master
    return;
  }
  fdl::DataUnit& du = reply_data(t, ResponseStatus::kDataLow);
  if (inputs) {
    fill_inputs(du, now);
  } else {
    du.assign(outputs_.begin(), outputs_.end());
  }
}

void Slave::on_set_slave_add(const fdl::Telegram& t, TimePoint now) {
  // [IEC 61158-6-3 Set_Slave_Add, Rd_Inp/Rd_Outp]: only in Wait_Prm, only if supported and not
  // locked by No_Add_Chg.
  if (!config_.set_slave_add_supported || state_ != State::kWaitPrm || address_locked_) {
    reply_rs(t);
    return;
  }
  reply_short_ack();  // sent from the old address: built before the change
  const auto decoded = pdu::decode_set_slave_add(bytes_of(t.data));
  if (!decoded) return;
  const pdu::SetSlaveAdd& ssa = decoded.value();
  if (ssa.new_address > pdu::sap::kMaxSlaveAddress || ssa.ident_number != config_.ident_number) {
    return;
  }
  address_ = ssa.new_address;
  address_locked_ = ssa.no_add_chg;
  fcb_.reset();
  app_.on_address_changed(
      ssa.new_address, ssa.no_add_chg,
      std::span<const std::uint8_t>(ssa.rem_slave_data.data(), ssa.rem_slave_data.size()), now);
  enter(State::kWaitPrm, TransitionReason::kAddressChanged, now);
}

}  // namespace rs4sim::dp::slave
