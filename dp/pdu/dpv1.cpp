// DPV1 MSAC_C1 PDUs, [IEC 61158-6-3 MSAC_C1, MSAC_C1 polling, DPV1 alarms].
#include "dp/pdu/dpv1.h"

#include "dp/pdu/dpv1_internal.h"
#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {
namespace internal {

bool known_function(std::uint8_t code) {
  switch (static_cast<Dpv1Function>(code)) {
    case Dpv1Function::kIdle:
    case Dpv1Function::kDataTransport:
    case Dpv1Function::kResourceManager:
    case Dpv1Function::kInitiate:
    case Dpv1Function::kAbort:
    case Dpv1Function::kAlarmAck:
    case Dpv1Function::kRead:
    case Dpv1Function::kWrite: return true;
  }
  return false;
}

Result<void> check_du(std::span<const std::uint8_t> du) {
  if (du.empty()) return PduError::kTooShort;
  if (du.size() > wire::kMaxDpDu) return PduError::kTooLong;
  return boost::outcome_v2::success();
}

Result<void> exact_size(std::span<const std::uint8_t> du, std::size_t n) {
  if (du.size() < n) return PduError::kTooShort;
  if (du.size() > n) return PduError::kLengthMismatch;
  return boost::outcome_v2::success();
}

// Slot Index Length Data…: Length must equal the data bytes present and be ≤ 240.
Result<Dpv1Data> data_with_length(std::span<const std::uint8_t> du) {
  if (du.size() < 4) return PduError::kTooShort;
  if (du[3] > kDpv1MaxData) return PduError::kValueOutOfRange;
  if (du.size() - 4 != du[3]) return PduError::kLengthMismatch;
  return Dpv1Data(du.begin() + 4, du.end());
}

Result<ReadRequest> decode_read_request(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(exact_size(du, 4));
  if (du[3] == 0 || du[3] > kDpv1MaxData) return PduError::kValueOutOfRange;
  return ReadRequest{du[1], du[2], du[3]};
}

Result<WriteRequest> decode_write_request(std::span<const std::uint8_t> du) {
  if (du.size() >= 4 && du[3] == 0) return PduError::kValueOutOfRange;
  BOOST_OUTCOME_TRY(data, data_with_length(du));
  return WriteRequest{du[1], du[2], std::move(data)};
}

Result<ReadResponse> decode_read_response(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(data, data_with_length(du));
  return ReadResponse{du[1], du[2], std::move(data)};
}

Result<WriteResponse> decode_write_response(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(exact_size(du, 4));
  if (du[3] > kDpv1MaxData) return PduError::kValueOutOfRange;
  return WriteResponse{du[1], du[2], du[3]};
}

Result<Dpv1Error> decode_negative(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(exact_size(du, 4));
  const auto code = static_cast<std::uint8_t>(du[0] & ~kDpv1ErrorBit);
  if (!known_function(code)) return PduError::kBadFunctionCode;
  return Dpv1Error{static_cast<Dpv1Function>(code), du[1], error_code_1_from_wire(du[2]), du[3]};
}

Result<AlarmAck> decode_alarm_ack(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(exact_size(du, 4));
  return AlarmAck{du[1], du[2], du[3]};
}

Result<void> encode_data_pdu(Dpv1Function f, std::uint8_t slot, std::uint8_t index,
                             std::span<const std::uint8_t> data, fdl::DataUnit& out) {
  if (data.size() > kDpv1MaxData) return PduError::kValueOutOfRange;
  if (out.size() + 4 + data.size() > wire::kMaxDpDu) return PduError::kTooLong;
  (void)wire::append(
      out, {static_cast<std::uint8_t>(f), slot, index, static_cast<std::uint8_t>(data.size())});
  return wire::append(out, data);
}

}  // namespace internal

using namespace internal;

Result<C1Request> decode_c1_request(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(check_du(du));
  switch (du[0]) {
    case fn(Dpv1Function::kRead): return as<C1Request>(decode_read_request(du));
    case fn(Dpv1Function::kWrite): return as<C1Request>(decode_write_request(du));
    case fn(Dpv1Function::kAlarmAck): return as<C1Request>(decode_alarm_ack(du));
    default: return PduError::kBadFunctionCode;
  }
}

Result<C1Response> decode_c1_response(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(check_du(du));
  if ((du[0] & kDpv1ErrorBit) != 0) return as<C1Response>(decode_negative(du));
  switch (du[0]) {
    case fn(Dpv1Function::kRead): return as<C1Response>(decode_read_response(du));
    case fn(Dpv1Function::kWrite): return as<C1Response>(decode_write_response(du));
    case fn(Dpv1Function::kAlarmAck): return as<C1Response>(decode_alarm_ack(du));
    default: return PduError::kBadFunctionCode;
  }
}

std::optional<Dpv1Error> c1_reject_response(std::span<const std::uint8_t> du) {
  if (du.empty()) return std::nullopt;
  if (du[0] == fn(Dpv1Function::kRead)) return type_conflict(Dpv1Function::kRead);
  if (du[0] == fn(Dpv1Function::kWrite)) return type_conflict(Dpv1Function::kWrite);
  return std::nullopt;
}

Result<void> encode(const ReadRequest& r, fdl::DataUnit& out) {
  if (r.length == 0 || r.length > kDpv1MaxData) return PduError::kValueOutOfRange;
  return wire::append(out,
                      {static_cast<std::uint8_t>(Dpv1Function::kRead), r.slot, r.index, r.length});
}

Result<void> encode(const ReadResponse& r, fdl::DataUnit& out) {
  return encode_data_pdu(Dpv1Function::kRead, r.slot, r.index, as_span(r.data), out);
}

Result<void> encode(const WriteRequest& r, fdl::DataUnit& out) {
  if (r.data.empty()) return PduError::kValueOutOfRange;
  return encode_data_pdu(Dpv1Function::kWrite, r.slot, r.index, as_span(r.data), out);
}

Result<void> encode(const WriteResponse& r, fdl::DataUnit& out) {
  if (r.length > kDpv1MaxData) return PduError::kValueOutOfRange;
  return wire::append(out,
                      {static_cast<std::uint8_t>(Dpv1Function::kWrite), r.slot, r.index, r.length});
}

Result<void> encode(const AlarmAck& a, fdl::DataUnit& out) {
  return wire::append(
      out, {static_cast<std::uint8_t>(Dpv1Function::kAlarmAck), a.slot, a.alarm_type, a.specifier});
}

Result<void> encode(const Dpv1Error& e, fdl::DataUnit& out) {
  if (!known_function(static_cast<std::uint8_t>(e.function))) return PduError::kBadFunctionCode;
  return wire::append(
      out, {static_cast<std::uint8_t>(static_cast<std::uint8_t>(e.function) | kDpv1ErrorBit),
            e.error_decode, to_wire(e.error_code_1), e.error_code_2});
}

}  // namespace rs4sim::dp::pdu
