// dp::Slave MSAC_C1 ([IEC 61158-6-3 MSAC_C1]), the poll pattern ([IEC 61158-6-3 MSAC_C1 polling])
// and Alarm_Ack ([IEC 61158-6-3 DPV1 alarms]).
#include "dp/pdu/dpv1.h"
#include "dp/pdu/sap.h"
#include "dp/slave/slave.h"
#include "dp/slave/slave_error.h"

#include <algorithm>
#include <variant>

namespace rs4sim::dp::slave {

namespace {
constexpr std::uint8_t kFnRead = 0x5E;
constexpr std::uint8_t kFnWrite = 0x5F;
constexpr std::uint8_t kFnAlarmAck = 0x5C;
}  // namespace

void Slave::close_dpv1() {
  c1_open_ = false;
  c1_ = AcyclicJob{};
  alarm_sap_ = AcyclicJob{};
  alarms_.close();
  alarm_in_diag_.reset();
}

void Slave::protocol_violation(TimePoint now) {
  // [IEC 61158-6-3 MSAC_C1, DPV1 alarms] [VPC3+ dp_msac1.c]: unknown function on SAP 51 or an
  // unmatched Alarm_Ack makes the slave leave data exchange; the master must parameterise it again.
  fault_to_wait_prm(TransitionReason::kProtocolViolation, false, now);
}

void Slave::on_msac_c1(const fdl::Telegram& t, TimePoint now) {
  const bool alarm_sap = *t.dsap == pdu::sap::kAlarm;
  // SAPs 50/51 are open only in DPV1 data exchange and only for the owner's SAP 51.
  if (!c1_open_ || !is_owner(t.sa) || *t.ssap != pdu::sap::kMasterMsac1 ||
      (alarm_sap && !config_.extra_alarm_sap)) {
    reply_rs(t);
    return;
  }
  AcyclicJob& job = alarm_sap ? alarm_sap_ : c1_;
  if (poll_job(job, t)) return;
  if (t.data[0] == kFnAlarmAck) {
    on_alarm_ack(job, t, now);
  } else if (alarm_sap) {
    reply_short_ack();
    protocol_violation(now);
  } else {
    start_c1_request(t, now);
  }
}

// [IEC 61158-6-3 MSAC_C1 polling]: an empty DU, or the DU of the request being served, is a poll:
// SC until the response is ready, then the response (FC DL). Another request while the application
// is still busy gets RR (no free indication buffer).
bool Slave::poll_job(AcyclicJob& job, const fdl::Telegram& t) {
  const bool same =
      job.phase != AcyclicJob::Phase::kIdle &&
      std::equal(t.data.begin(), t.data.end(), job.request.begin(), job.request.end());
  if (t.data.empty() || same) {
    if (job.phase == AcyclicJob::Phase::kReady) {
      reply_data(t, fdl::ResponseStatus::kDataLow) = job.response;
      job.phase = AcyclicJob::Phase::kIdle;
      job.request.clear();
    } else {
      reply_short_ack();
    }
    return true;
  }
  if (job.phase == AcyclicJob::Phase::kWaitingForApp) {
    reply_status(t, fdl::ResponseStatus::kNoResource);
    return true;
  }
  return false;  // a new request; an unfetched ready response is dropped
}

void Slave::fail_job(AcyclicJob& job, pdu::ErrorCode1 code_1) {
  job.response = {static_cast<std::uint8_t>(job.function | 0x80), 0x80, pdu::to_wire(code_1), 0x00};
  job.phase = AcyclicJob::Phase::kReady;
}

void Slave::start_c1_request(const fdl::Telegram& t, TimePoint now) {
  reply_short_ack();  // [IEC 61158-6-3 MSAC_C1 polling] step 2: the response comes on a later poll
  c1_.request = t.data;
  c1_.function = t.data[0];
  c1_.close_after_send = false;
  const auto decoded = pdu::decode_c1_request(bytes_of(t.data));
  if (!decoded) {
    // [IEC 61158-6-3 MSAC_C1] [VPC3+ dp_msac1.c]: a malformed Read/Write gets DE/DF 80 B3 00;
    // anything else (unknown function) makes the slave leave data exchange.
    if (const auto neg = pdu::c1_reject_response(bytes_of(t.data))) {
      fail_job(c1_, neg->error_code_1);
    } else {
      protocol_violation(now);
    }
    return;
  }
  AcyclicRequest req;
  req.channel = AcyclicChannel::kC1;
  req.master_address = t.sa;
  if (const auto* r = std::get_if<pdu::ReadRequest>(&decoded.value())) {
    if (r->length > config_.c1_max_data_length) {  // beyond C1_Max_Data_Len
      fail_job(c1_, pdu::ErrorCode1::kTypeConflict);
      return;
    }
    req.service = AcyclicService::kRead;
    req.slot = r->slot;
    req.index = r->index;
    req.length = r->length;
  } else if (const auto* w = std::get_if<pdu::WriteRequest>(&decoded.value())) {
    if (w->data.size() > config_.c1_max_data_length) {
      fail_job(c1_, pdu::ErrorCode1::kWriteLengthError);
      return;
    }
    req.service = AcyclicService::kWrite;
    req.slot = w->slot;
    req.index = w->index;
    req.length = static_cast<std::uint8_t>(w->data.size());
    req.data = std::span<const std::uint8_t>(t.data.data() + 4, w->data.size());
  } else {
    protocol_violation(now);  // Alarm_Ack is routed before; nothing else is valid here
    return;
  }
  run_acyclic(c1_, req, now);
}

void Slave::run_acyclic(AcyclicJob& job, const AcyclicRequest& req, TimePoint now) {
  job.phase = AcyclicJob::Phase::kWaitingForApp;
  const AcyclicResult r = app_.on_acyclic(req, now);
  // The application may also have called complete_acyclic() from inside on_acyclic().
  if (r.kind != AcyclicResult::Kind::kPending && job.phase == AcyclicJob::Phase::kWaitingForApp) {
    if (finish_job(job, r)) fail_job(job, pdu::ErrorCode1::kReadError);
  }
}

std::error_code Slave::finish_job(AcyclicJob& job, const AcyclicResult& r) {
  if (r.kind == AcyclicResult::Kind::kError) {
    const auto& e = r.error;
    job.response = {static_cast<std::uint8_t>(job.function | 0x80), e.error_decode,
                    pdu::to_wire(e.error_code_1), e.error_code_2};
    job.phase = AcyclicJob::Phase::kReady;
    return {};
  }
  const std::uint8_t wanted = job.request.size() >= 4 ? job.request[3] : 0;
  if (job.function == kFnWrite) {  // Write.res+ = the 4-byte header, no data
                                   // ([IEC 61158-6-3 MSAC_C1])
    job.response.assign(job.request.begin(), job.request.begin() + 4);
  } else {
    // Read.res+: Length = bytes actually returned, ≤ requested ([IEC 61158-6-3 MSAC_C1]).
    if (r.data.size() > kMaxAcyclicData || (job.function == kFnRead && r.data.size() > wanted)) {
      return SlaveError::kResponseTooLong;
    }
    job.response = {job.function, job.request[1], job.request[2],
                    static_cast<std::uint8_t>(r.data.size())};
    job.response.insert(job.response.end(), r.data.begin(), r.data.end());
  }
  job.phase = AcyclicJob::Phase::kReady;
  return {};
}

std::error_code Slave::complete_acyclic(AcyclicChannel channel, const AcyclicResult& r) {
  AcyclicJob& job = channel == AcyclicChannel::kC1 ? c1_ : c2_.job;
  if (job.phase != AcyclicJob::Phase::kWaitingForApp) return SlaveError::kNoPendingRequest;
  if (r.kind == AcyclicResult::Kind::kPending) return {};
  const auto ec = finish_job(job, r);
  wake();
  return ec;
}

void Slave::on_alarm_ack(AcyclicJob& job, const fdl::Telegram& t, TimePoint now) {
  reply_short_ack();
  const auto& pdu = t.data;
  // Alarm_Ack.req 5C Slot Alarm_Type Alarm_Specifier, matched on (slot, type, Seq_Nr).
  if (pdu.size() != 4 || !alarms_.is_open() ||
      !alarms_.acknowledge(pdu[1], pdu[2], static_cast<std::uint8_t>(pdu[3] >> 3))) {
    protocol_violation(now);
    return;
  }
  job.request = pdu;
  job.function = kFnAlarmAck;
  job.response = pdu;  // Alarm_Ack.res+ = 4-byte echo, FC DL [VPC3+ dp_msac1.c]
  job.phase = AcyclicJob::Phase::kReady;
  app_.on_alarm_acknowledged({pdu[2], pdu[1], static_cast<std::uint8_t>(pdu[3] >> 3)}, now);
  promote_alarm();
}

}  // namespace rs4sim::dp::slave
