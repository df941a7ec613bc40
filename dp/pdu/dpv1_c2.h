#pragma once
// DPV1 MSAC_C2 PDUs (class-2, connection oriented), [IEC 61158-6-3 MSAC_C2]:
// resource-manager reply, Initiate, Abort, Data_Transport, Idle; Read/Write are the C1
// PDUs of dpv1.h on the connection SAP.
//
//   RM.res        56 SAP_Nr Send_Timeout(BE)
//   Initiate.req  57 00 00 00 Send_Timeout(BE) Feat1 Feat2 ProfFeat1 ProfFeat2 ProfIdent(BE)
//                 S_Type S_Len D_Type D_Len S_Addr[S_Len] D_Addr[D_Len]
//   Initiate.res  57 Max_Len_Data_Unit Feat1 Feat2 ProfFeat1 ProfFeat2 ProfIdent(BE)
//                 S_Type S_Len D_Type D_Len S_Addr[S_Len] D_Addr[D_Len]
//   Abort         58 Subnet Instance|Reason Reserved
//   Data_Transport 51 Slot Index Length Data   (request and response; neg. D1)
//   Idle          48 [+ 1 byte, UNCERTAIN [docs/decisions.md#dp-open-points]]

#include "dp/fdl/telegram.h"
#include "dp/pdu/dpv1.h"
#include "dp/pdu/errors.h"

#include <boost/container/static_vector.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>

namespace rs4sim::dp::pdu {

inline constexpr std::size_t kInitiateReqHead = 16;
inline constexpr std::size_t kInitiateResHead = 12;

using C2Address = boost::container::static_vector<std::uint8_t, kDpv1MaxData>;

struct ResourceManagerResponse {
  std::uint8_t sap = 0;            // connection SAP 0…48
  std::uint16_t send_timeout = 0;  // unit 10 ms
  friend bool operator==(const ResourceManagerResponse&, const ResourceManagerResponse&) = default;
};

struct InitiateRequest {
  std::uint16_t send_timeout = 0;  // unit 10 ms
  std::array<std::uint8_t, 2> features_supported{0x01, 0x00};
  std::array<std::uint8_t, 2> profile_features_supported{};
  std::uint16_t profile_ident_number = 0;
  std::uint8_t s_type = 0;
  std::uint8_t d_type = 0;
  C2Address s_addr;  // S_Len bytes
  C2Address d_addr;  // D_Len bytes
  friend bool operator==(const InitiateRequest&, const InitiateRequest&) = default;
};

struct InitiateResponse {
  std::uint8_t max_len_data_unit = 0;
  std::array<std::uint8_t, 2> features_supported{0x01, 0x00};
  std::array<std::uint8_t, 2> profile_features_supported{};
  std::uint16_t profile_ident_number = 0;
  std::uint8_t s_type = 0;
  std::uint8_t d_type = 0;
  C2Address s_addr;
  C2Address d_addr;
  friend bool operator==(const InitiateResponse&, const InitiateResponse&) = default;
};

// Abort subnet ([IEC 61158-6-3 MSAC_C2]).
enum class AbortSubnet : std::uint8_t { kNone = 0, kLocal = 1, kRemote = 2 };
// Abort instance, bits 5..4.
enum class AbortInstance : std::uint8_t { kFdl = 0, kMsacC2 = 1, kUser = 2 };
// Abort reasons for instance MSAC_C2 (bits 3..0).
namespace abort_reason {
inline constexpr std::uint8_t kSequenceError = 1;
inline constexpr std::uint8_t kInvalidRequestPdu = 2;
inline constexpr std::uint8_t kTimeout = 3;
inline constexpr std::uint8_t kInvalidResponsePdu = 4;
inline constexpr std::uint8_t kInvalidUserService = 5;
inline constexpr std::uint8_t kSendTimeoutTooSmall = 6;
inline constexpr std::uint8_t kInvalidAddressInfo = 7;
inline constexpr std::uint8_t kWaitingForReply = 8;
inline constexpr std::uint8_t kResource = 15;
}  // namespace abort_reason

struct Abort {
  AbortSubnet subnet = AbortSubnet::kNone;
  AbortInstance instance = AbortInstance::kMsacC2;
  std::uint8_t reason = 0;    // bits 3..0
  std::uint8_t reserved = 0;  // 4th byte
  friend bool operator==(const Abort&, const Abort&) = default;
};

struct DataTransport {
  std::uint8_t slot = 0;
  std::uint8_t index = 0;
  Dpv1Data data;
  friend bool operator==(const DataTransport&, const DataTransport&) = default;
};

struct Idle {
  std::optional<std::uint8_t> second_byte;  // UNCERTAIN ([docs/decisions.md#dp-open-points]): 1-
                                            // and 2-byte forms accepted
  friend bool operator==(const Idle&, const Idle&) = default;
};

using C2Request =
    std::variant<InitiateRequest, Abort, ReadRequest, WriteRequest, DataTransport, Idle>;
using C2Response = std::variant<InitiateResponse, Abort, ReadResponse, WriteResponse, DataTransport,
                                Idle, Dpv1Error>;

// Errors: kTooShort, kTooLong (DU > 244, or Idle > 2 bytes), kBadFunctionCode,
// kLengthMismatch (address/data counts disagree with the bytes present), kValueOutOfRange
// (Abort subnet > 2 / instance > 2).
Result<ResourceManagerResponse> decode_rm_response(std::span<const std::uint8_t> du);
Result<C2Request> decode_c2_request(std::span<const std::uint8_t> du);
Result<C2Response> decode_c2_response(std::span<const std::uint8_t> du);

Result<void> encode(const ResourceManagerResponse& r, fdl::DataUnit& out);
Result<void> encode(const InitiateRequest& r, fdl::DataUnit& out);
Result<void> encode(const InitiateResponse& r, fdl::DataUnit& out);
Result<void> encode(const Abort& a, fdl::DataUnit& out);
Result<void> encode(const DataTransport& d, fdl::DataUnit& out);
Result<void> encode(const Idle& i, fdl::DataUnit& out);

}  // namespace rs4sim::dp::pdu
