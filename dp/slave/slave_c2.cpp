// dp::Slave MSAC_C2 ([IEC 61158-6-3 MSAC_C2]): resource manager on SAP 49, one connection at a time
// on the dynamic SAP config.c2_sap, Initiate/Abort/Idle/Read/Write/Data_Transport, idle timeout.
#include "codec/endian.h"
#include "dp/pdu/dpv1_c2.h"
#include "dp/pdu/sap.h"
#include "dp/slave/slave.h"

#include <algorithm>
#include <chrono>
#include <variant>

namespace rs4sim::dp::slave {

namespace {
constexpr std::uint8_t kFnIdle = 0x48;
constexpr std::uint8_t kFnDataTransport = 0x51;
constexpr std::uint8_t kFnResourceManager = 0x56;
constexpr std::uint8_t kFnInitiate = 0x57;
constexpr std::uint8_t kFnAbort = 0x58;
constexpr std::uint8_t kFnRead = 0x5E;
constexpr std::uint8_t kFnWrite = 0x5F;

// Abort PDU `58 Subnet Instance|Reason 00`, instance MSAC_C2 (bits 5..4 = 01)
// ([IEC 61158-6-3 MSAC_C2]).
enum class AbortReason : std::uint8_t {
  kInvalidRequestPdu = 2,
  kTimeout = 3,
  kSendTimeoutTooSmall = 6,
  kInvalidAddressInfo = 7,
};
fdl::DataUnit abort_pdu(AbortReason r) {
  return {kFnAbort, 0x00, static_cast<std::uint8_t>(0x10 | static_cast<std::uint8_t>(r)), 0x00};
}

}  // namespace

void Slave::c2_close(C2Event why, TimePoint now) {
  const std::uint8_t master = c2_.master;
  c2_ = C2Connection{};
  app_.on_c2_event(why, master, now);
}

void Slave::on_c2_rm(const fdl::Telegram& t, TimePoint now) {
  // [IEC 61158-6-3 MSAC_C2] step 2: with the connection SAP taken (or C2 off) the RM is not loaded
  // → RS.
  if (!config_.c2_supported || c2_.bound || t.data.empty() || t.data[0] != kFnInitiate) {
    reply_rs(t);
    return;
  }
  c2_.bound = true;
  c2_.master = t.sa;
  c2_.master_sap = *t.ssap;
  c2_.job.request = t.data;
  c2_.job.function = kFnInitiate;
  c2_.job.phase = AcyclicJob::Phase::kReady;
  c2_.send_timeout = std::chrono::milliseconds(10) * config_.c2_rm_send_timeout;
  const auto decoded = pdu::decode_c2_request(bytes_of(t.data));
  const auto* init = decoded ? std::get_if<pdu::InitiateRequest>(&decoded.value()) : nullptr;
  C2Event event = C2Event::kRefused;
  if (init == nullptr) {
    const bool addr = !decoded && decoded.error() == pdu::PduError::kLengthMismatch;
    c2_.job.response =
        abort_pdu(addr ? AbortReason::kInvalidAddressInfo : AbortReason::kInvalidRequestPdu);
  } else if (init->send_timeout == 0) {
    c2_.job.response = abort_pdu(AbortReason::kSendTimeoutTooSmall);
  } else {
    // Initiate.res (UNCERTAIN [docs/decisions.md#dp-open-points]): our Max_Len_Data_Unit and
    // features (01 00), the profile fields echoed, the address blocks with source and destination
    // swapped.
    pdu::InitiateResponse res;
    res.max_len_data_unit = static_cast<std::uint8_t>(config_.c2_max_data_length + 4);
    res.profile_features_supported = init->profile_features_supported;
    res.profile_ident_number = init->profile_ident_number;
    res.s_type = init->d_type;
    res.d_type = init->s_type;
    res.s_addr = init->d_addr;
    res.d_addr = init->s_addr;
    c2_.job.response.clear();
    if (pdu::encode(res, c2_.job.response)) {
      c2_.established = true;
      c2_.send_timeout = std::chrono::milliseconds(10) * init->send_timeout;
      event = C2Event::kConnected;
    } else {
      c2_.job.response = abort_pdu(AbortReason::kInvalidAddressInfo);
    }
  }
  c2_.job.close_after_send = !c2_.established;
  c2_.deadline = now + c2_.send_timeout;
  // Immediate RM reply `56 SAP Send_Timeout` with FC DL [VPC3+ dp_if.h FDL_RM_ANSWER].
  reply_data(t, fdl::ResponseStatus::kDataLow) = {kFnResourceManager, config_.c2_sap,
                                                  codec::high_byte(config_.c2_rm_send_timeout),
                                                  codec::low_byte(config_.c2_rm_send_timeout)};
  app_.on_c2_event(event, t.sa, now);
}

void Slave::on_c2_sap(const fdl::Telegram& t, TimePoint now) {
  if (!c2_.bound || t.sa != c2_.master || *t.ssap != c2_.master_sap) {
    reply_rs(t);
    return;
  }
  c2_.deadline = now + c2_.send_timeout;  // every request retriggers ([IEC 61158-6-3 MSAC_C2]
                                          // step 5)
  if (c2_.job.close_after_send && c2_.job.phase == AcyclicJob::Phase::kReady) {
    // A refused Initiate or a slave Abort: whatever the master sends next gets the Abort,
    // then the SAP is free again.
    reply_data(t, fdl::ResponseStatus::kDataLow) = c2_.job.response;
    if (c2_.established) {
      c2_close(C2Event::kAbortedBySlave, now);
    } else {
      c2_ = C2Connection{};  // kRefused was reported with the Initiate
    }
    return;
  }
  if (poll_job(c2_.job, t)) return;
  start_c2_request(t, now);
}

void Slave::start_c2_request(const fdl::Telegram& t, TimePoint now) {
  reply_short_ack();
  const auto& pdu = t.data;
  AcyclicJob& job = c2_.job;
  job.request = pdu;
  job.function = pdu[0];
  if (pdu[0] == kFnAbort) {
    c2_close(C2Event::kAbortedByMaster, now);
    return;
  }
  if (pdu[0] == kFnIdle) {
    job.request.clear();  // keep-alive: nothing to answer
    job.phase = AcyclicJob::Phase::kIdle;
    return;
  }
  AcyclicRequest req;
  req.channel = AcyclicChannel::kC2;
  req.master_address = t.sa;
  const bool known = pdu[0] == kFnRead || pdu[0] == kFnWrite || pdu[0] == kFnDataTransport;
  if (!known || pdu.size() < 4) {
    job.function = kFnAbort;
    job.response = abort_pdu(AbortReason::kInvalidRequestPdu);
    job.phase = AcyclicJob::Phase::kReady;
    job.close_after_send = true;
    return;
  }
  req.slot = pdu[1];
  req.index = pdu[2];
  req.length = pdu[3];
  if (pdu[0] == kFnRead) {
    if (pdu.size() != 4 || pdu[3] == 0 || pdu[3] > config_.c2_max_data_length) {
      fail_job(job, pdu::ErrorCode1::kTypeConflict);
      return;
    }
    req.service = AcyclicService::kRead;
  } else {
    // Same rules as C1 (dp/pdu c1_reject_response): Length 0 or ≠ data → B3; more than
    // C2_Max_Data_Len → B1 (write length error).
    if ((pdu[3] == 0 && pdu[0] == kFnWrite) || pdu.size() != 4U + pdu[3]) {
      fail_job(job, pdu::ErrorCode1::kTypeConflict);
      return;
    }
    if (pdu[3] > config_.c2_max_data_length) {
      fail_job(job, pdu::ErrorCode1::kWriteLengthError);
      return;
    }
    req.service = pdu[0] == kFnWrite ? AcyclicService::kWrite : AcyclicService::kDataTransport;
    req.data = std::span<const std::uint8_t>(pdu.data() + 4, pdu[3]);
    if (pdu[0] == kFnWrite) {
      req.first_write_after_initiate = !c2_.first_write_seen;
      c2_.first_write_seen = true;
    }
  }
  run_acyclic(job, req, now);
}

}  // namespace rs4sim::dp::slave
