#pragma once
// DPV1 MSAC_C1 PDUs (slave DSAP 51, Alarm_Ack also DSAP 50),
// [IEC 61158-6-3 MSAC_C1, MSAC_C1 polling, DPV1 alarms]: Read, Write, Alarm_Ack requests and
// responses, and the negative response.
//
//   Read.req    5E Slot Index Length              Read.res+   5E Slot Index Length Data
//   Write.req   5F Slot Index Length Data         Write.res+  5F Slot Index Length
//   Alarm_Ack   5C Slot Alarm_Type Specifier      (response = echo of the request)
//   Neg.res     (Fn|0x80) Error_Decode Error_Code_1 Error_Code_2

#include "dp/fdl/telegram.h"
#include "dp/pdu/error_code_1.h"
#include "dp/pdu/errors.h"

#include <boost/container/static_vector.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <variant>

namespace rs4sim::dp::pdu {

inline constexpr std::size_t kDpv1MaxData = 240;  // 4-byte header + 240 = 244
                                                  // ([IEC 61158-6-3 MSAC_C1])

// DPV1 function numbers ([IEC 61158-6-3 MSAC_C1]). Negative response = function | 0x80.
enum class Dpv1Function : std::uint8_t {
  kIdle = 0x48,             // C2
  kDataTransport = 0x51,    // C2
  kResourceManager = 0x56,  // C2
  kInitiate = 0x57,         // C2
  kAbort = 0x58,            // C2
  kAlarmAck = 0x5C,         // C1
  kRead = 0x5E,             // C1/C2
  kWrite = 0x5F,            // C1/C2
};
inline constexpr std::uint8_t kDpv1ErrorBit = 0x80;

// Error_Decode ([IEC 61158-6-3 MSAC_C1]).
namespace error_decode {
inline constexpr std::uint8_t kDpv1 = 0x80;
inline constexpr std::uint8_t kFms = 0xFE;
inline constexpr std::uint8_t kHart = 0xFF;
}  // namespace error_decode

// Error_Code_1: ErrorCode1 in error_code_1.h.

using Dpv1Data = boost::container::static_vector<std::uint8_t, kDpv1MaxData>;

struct ReadRequest {
  std::uint8_t slot = 0;
  std::uint8_t index = 0;
  std::uint8_t length = 1;  // max bytes wanted, 1…240
  friend bool operator==(const ReadRequest&, const ReadRequest&) = default;
};
struct ReadResponse {
  std::uint8_t slot = 0;
  std::uint8_t index = 0;
  Dpv1Data data;  // Length field = data.size()
  friend bool operator==(const ReadResponse&, const ReadResponse&) = default;
};
struct WriteRequest {
  std::uint8_t slot = 0;
  std::uint8_t index = 0;
  Dpv1Data data;  // 1…240 bytes
  friend bool operator==(const WriteRequest&, const WriteRequest&) = default;
};
struct WriteResponse {
  std::uint8_t slot = 0;
  std::uint8_t index = 0;
  std::uint8_t length = 0;  // bytes written
  friend bool operator==(const WriteResponse&, const WriteResponse&) = default;
};
// Alarm_Ack request and positive response have the same 4 bytes ([IEC 61158-6-3 DPV1 alarms]).
struct AlarmAck {
  std::uint8_t slot = 0;
  std::uint8_t alarm_type = 0;
  std::uint8_t specifier = 0;  // Alarm_Specifier byte: Seq_Nr<<3 | Add_Ack<<2 | specifier
  [[nodiscard]] std::uint8_t seq_nr() const { return static_cast<std::uint8_t>(specifier >> 3); }
  friend bool operator==(const AlarmAck&, const AlarmAck&) = default;
};
// Negative response of any DPV1 service (C1 and C2).
struct Dpv1Error {
  Dpv1Function function = Dpv1Function::kRead;  // the failed service (wire: | 0x80)
  std::uint8_t error_decode = error_decode::kDpv1;
  ErrorCode1 error_code_1 = ErrorCode1::kNone;
  std::uint8_t error_code_2 = 0;
  friend bool operator==(const Dpv1Error&, const Dpv1Error&) = default;
};

using C1Request = std::variant<ReadRequest, WriteRequest, AlarmAck>;
using C1Response = std::variant<ReadResponse, WriteResponse, AlarmAck, Dpv1Error>;

// Slave side. Errors: kTooShort, kTooLong (DU > 244), kBadFunctionCode (anything but 5E/5F/5C — the
// slave leaves data exchange, [IEC 61158-6-3 MSAC_C1]), kLengthMismatch (Read.req not exactly 4
// bytes, Write data count ≠ Length), kValueOutOfRange (Read Length 0 or > 240, Write Length 0). A
// malformed Read/Write is answered with a negative response (see c1_reject_response).
Result<C1Request> decode_c1_request(std::span<const std::uint8_t> du);
// Master side. Errors: kTooShort, kTooLong (DU > 244), kBadFunctionCode, kLengthMismatch (Read.res
// data count ≠ Length, Write.res/Alarm_Ack/Neg.res not exactly 4 bytes), kValueOutOfRange (Length >
// 240).
Result<C1Response> decode_c1_response(std::span<const std::uint8_t> du);

// Encoders (Errors: kValueOutOfRange for Length 0/ > 240 where the PDU forbids it).
Result<void> encode(const ReadRequest& r, fdl::DataUnit& out);
Result<void> encode(const ReadResponse& r, fdl::DataUnit& out);
Result<void> encode(const WriteRequest& r, fdl::DataUnit& out);
Result<void> encode(const WriteResponse& r, fdl::DataUnit& out);
Result<void> encode(const AlarmAck& a, fdl::DataUnit& out);
Result<void> encode(const Dpv1Error& e, fdl::DataUnit& out);

// The negative response the slave sends for a malformed Read/Write ([IEC 61158-6-3 MSAC_C1]
// [VPC3+ dp_msac1.c]).
constexpr Dpv1Error type_conflict(Dpv1Function f) {
  return Dpv1Error{f, error_decode::kDpv1, ErrorCode1::kTypeConflict, 0};
}

// What a slave answers to a C1 request that decode_c1_request() rejected ([IEC 61158-6-3 MSAC_C1]):
// a Read or Write PDU gets type_conflict(Read/Write) (e.g. DE 80 B3 00); for anything else (unknown
// function, malformed Alarm_Ack, empty DU) nullopt = no PDU reply, the slave leaves data exchange.
std::optional<Dpv1Error> c1_reject_response(std::span<const std::uint8_t> du);

}  // namespace rs4sim::dp::pdu
