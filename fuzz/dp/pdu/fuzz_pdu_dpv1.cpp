// libFuzzer target: DPV1 MSAC_C1 request/response decoders
// ([IEC 61158-6-3 MSAC_C1, MSAC_C1 polling, DPV1 alarms]). Every accepted PDU re-encodes to exactly
// the input bytes; the data part is also read as an I&M call (+ I&M0 record) and must re-encode
// exactly.
#include "dp/pdu/dpv1.h"
#include "dp/pdu/im.h"
#include "fuzz_check.h"

using namespace rs4sim::dp::pdu;

namespace {

template <class Variant>
void reencode_exact(const Variant& v, std::span<const std::uint8_t> du) {
  rs4sim::dp::fdl::DataUnit out;
  const auto r = std::visit([&](const auto& pdu) { return encode(pdu, out); }, v);
  rs4sim::dp::pdu::fuzz::check(r.has_value());
  rs4sim::dp::pdu::fuzz::check(rs4sim::dp::pdu::fuzz::same(out, du));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> du(data, size);
  if (const auto req = decode_c1_request(du)) reencode_exact(req.value(), du);
  if (const auto res = decode_c1_response(du)) reencode_exact(res.value(), du);
  if (const auto call = decode_im_call(du)) {
    rs4sim::dp::fdl::DataUnit out;
    fuzz::check(encode_im_call(call.value().header, out).has_value());
    if (const auto im0 = decode_im0(call.value().record)) {
      fuzz::check(encode_im0(im0.value(), out).has_value());
      fuzz::check(fuzz::same(out, du));
    } else {
      fuzz::check(call.value().record.size() != kImRecordLength);
    }
  }
  return 0;
}
