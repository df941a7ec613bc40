// DPV1 MSAC_C2 PDUs, [IEC 61158-6-3 MSAC_C2].
#include "dp/pdu/dpv1_c2.h"

#include "dp/pdu/dpv1_internal.h"
#include "dp/pdu/sap.h"
#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {
namespace {

using namespace internal;

// S_Addr / D_Addr after a head of `head` bytes whose S_Len/D_Len sit at head−3 / head−1.
Result<void> decode_addresses(std::span<const std::uint8_t> du, std::size_t head, C2Address& s,
                              C2Address& d) {
  const std::size_t s_len = du[head - 3];
  const std::size_t d_len = du[head - 1];
  if (du.size() != head + s_len + d_len) return PduError::kLengthMismatch;
  const auto* p = du.data() + head;
  s.assign(p, p + s_len);
  d.assign(p + s_len, p + s_len + d_len);
  return boost::outcome_v2::success();
}

// The fields Initiate request and response share, from byte `at` on: Features_Supported,
// Profile_Features_Supported, Profile_Ident_Number, S_Type, (S_Len,) D_Type, (D_Len,) then
// the addresses after the head of `head` bytes.
template <class Initiate>
Result<void> decode_initiate_fields(std::span<const std::uint8_t> du, std::size_t at,
                                    std::size_t head, Initiate& r) {
  r.features_supported = {du[at], du[at + 1]};
  r.profile_features_supported = {du[at + 2], du[at + 3]};
  r.profile_ident_number = codec::be16(du[at + 4], du[at + 5]);
  r.s_type = du[at + 6];
  r.d_type = du[at + 8];
  return decode_addresses(du, head, r.s_addr, r.d_addr);
}

Result<InitiateRequest> decode_initiate_request(std::span<const std::uint8_t> du) {
  if (du.size() < kInitiateReqHead) return PduError::kTooShort;
  InitiateRequest r;
  r.send_timeout = codec::be16(du[4], du[5]);
  BOOST_OUTCOME_TRY(decode_initiate_fields(du, 6, kInitiateReqHead, r));
  return r;
}

Result<InitiateResponse> decode_initiate_response(std::span<const std::uint8_t> du) {
  if (du.size() < kInitiateResHead) return PduError::kTooShort;
  InitiateResponse r;
  r.max_len_data_unit = du[1];
  BOOST_OUTCOME_TRY(decode_initiate_fields(du, 2, kInitiateResHead, r));
  return r;
}

Result<Abort> decode_abort(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(exact_size(du, 4));
  const unsigned instance = (du[2] >> 4) & 0x03U;
  if (du[1] > 2 || instance > 2 || (du[2] & 0xC0U) != 0) return PduError::kValueOutOfRange;
  return Abort{static_cast<AbortSubnet>(du[1]), static_cast<AbortInstance>(instance),
               static_cast<std::uint8_t>(du[2] & 0x0FU), du[3]};
}

Result<DataTransport> decode_transport(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(data, data_with_length(du));
  return DataTransport{du[1], du[2], std::move(data)};
}

Result<Idle> decode_idle(std::span<const std::uint8_t> du) {
  if (du.size() > 2) return PduError::kTooLong;
  Idle i;
  if (du.size() == 2) i.second_byte = du[1];
  return i;
}

Result<void> encode_addresses(std::uint8_t s_type, const C2Address& s, std::uint8_t d_type,
                              const C2Address& d, std::size_t head, fdl::DataUnit& out) {
  if (s.size() > 0xFF || d.size() > 0xFF) return PduError::kValueOutOfRange;
  if (out.size() + head + s.size() + d.size() > wire::kMaxDpDu) return PduError::kTooLong;
  (void)wire::append(out, {s_type, static_cast<std::uint8_t>(s.size()), d_type,
                           static_cast<std::uint8_t>(d.size())});
  (void)wire::append(out, s);
  return wire::append(out, d);
}

}  // namespace

Result<ResourceManagerResponse> decode_rm_response(std::span<const std::uint8_t> du) {
  BOOST_OUTCOME_TRY(exact_size(du, 4));
  if (du[0] != static_cast<std::uint8_t>(Dpv1Function::kResourceManager))
    return PduError::kBadFunctionCode;
  if (du[1] > sap::kMsacC2Max) return PduError::kValueOutOfRange;
  return ResourceManagerResponse{du[1], codec::be16(du[2], du[3])};
}

namespace {

// The C2 services of one direction: Initiate, Read and Write differ between request and
// response, Abort, Data_Transport and Idle are the same ([IEC 61158-6-3 MSAC_C2]).
template <class Out, class Initiate, class Read, class Write>
Result<Out> decode_c2(std::span<const std::uint8_t> du,
                      Result<Initiate> (*initiate)(std::span<const std::uint8_t>),
                      Result<Read> (*read)(std::span<const std::uint8_t>),
                      Result<Write> (*write)(std::span<const std::uint8_t>)) {
  BOOST_OUTCOME_TRY(check_du(du));
  switch (du[0]) {
    case fn(Dpv1Function::kInitiate): return as<Out>(initiate(du));
    case fn(Dpv1Function::kAbort): return as<Out>(decode_abort(du));
    case fn(Dpv1Function::kRead): return as<Out>(read(du));
    case fn(Dpv1Function::kWrite): return as<Out>(write(du));
    case fn(Dpv1Function::kDataTransport): return as<Out>(decode_transport(du));
    case fn(Dpv1Function::kIdle): return as<Out>(decode_idle(du));
    default: return PduError::kBadFunctionCode;
  }
}

}  // namespace

Result<C2Request> decode_c2_request(std::span<const std::uint8_t> du) {
  return decode_c2<C2Request>(du, decode_initiate_request, decode_read_request,
                              decode_write_request);
}

Result<C2Response> decode_c2_response(std::span<const std::uint8_t> du) {
  if (!du.empty() && (du[0] & kDpv1ErrorBit) != 0) {
    BOOST_OUTCOME_TRY(check_du(du));
    return as<C2Response>(decode_negative(du));
  }
  return decode_c2<C2Response>(du, decode_initiate_response, decode_read_response,
                               decode_write_response);
}

Result<void> encode(const ResourceManagerResponse& r, fdl::DataUnit& out) {
  if (r.sap > sap::kMsacC2Max) return PduError::kValueOutOfRange;
  return wire::append(out, {static_cast<std::uint8_t>(Dpv1Function::kResourceManager), r.sap,
                            codec::high_byte(r.send_timeout), codec::low_byte(r.send_timeout)});
}

Result<void> encode(const InitiateRequest& r, fdl::DataUnit& out) {
  if (out.size() + kInitiateReqHead + r.s_addr.size() + r.d_addr.size() > wire::kMaxDpDu) {
    return PduError::kTooLong;
  }
  (void)wire::append(
      out,
      {static_cast<std::uint8_t>(Dpv1Function::kInitiate), 0, 0, 0,
       codec::high_byte(r.send_timeout), codec::low_byte(r.send_timeout), r.features_supported[0],
       r.features_supported[1], r.profile_features_supported[0], r.profile_features_supported[1],
       codec::high_byte(r.profile_ident_number), codec::low_byte(r.profile_ident_number)});
  return encode_addresses(r.s_type, r.s_addr, r.d_type, r.d_addr, 4, out);
}

Result<void> encode(const InitiateResponse& r, fdl::DataUnit& out) {
  if (out.size() + kInitiateResHead + r.s_addr.size() + r.d_addr.size() > wire::kMaxDpDu) {
    return PduError::kTooLong;
  }
  (void)wire::append(
      out, {static_cast<std::uint8_t>(Dpv1Function::kInitiate), r.max_len_data_unit,
            r.features_supported[0], r.features_supported[1], r.profile_features_supported[0],
            r.profile_features_supported[1], codec::high_byte(r.profile_ident_number),
            codec::low_byte(r.profile_ident_number)});
  return encode_addresses(r.s_type, r.s_addr, r.d_type, r.d_addr, 4, out);
}

Result<void> encode(const Abort& a, fdl::DataUnit& out) {
  if (static_cast<unsigned>(a.subnet) > 2 || static_cast<unsigned>(a.instance) > 2 ||
      a.reason > 15) {
    return PduError::kValueOutOfRange;
  }
  return wire::append(
      out,
      {static_cast<std::uint8_t>(Dpv1Function::kAbort), static_cast<std::uint8_t>(a.subnet),
       static_cast<std::uint8_t>((static_cast<unsigned>(a.instance) << 4) | a.reason), a.reserved});
}

Result<void> encode(const DataTransport& d, fdl::DataUnit& out) {
  return encode_data_pdu(Dpv1Function::kDataTransport, d.slot, d.index, as_span(d.data), out);
}

Result<void> encode(const Idle& i, fdl::DataUnit& out) {
  BOOST_OUTCOME_TRY(wire::append(out, {static_cast<std::uint8_t>(Dpv1Function::kIdle)}));
  if (i.second_byte) return wire::append(out, {*i.second_byte});
  return boost::outcome_v2::success();
}

}  // namespace rs4sim::dp::pdu
