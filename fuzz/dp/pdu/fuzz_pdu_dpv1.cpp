// libFuzzer target: DPV1 MSAC_C1 request/response decoders (spec/profibus-dp.md §3.3–§3.5).
// Every accepted PDU re-encodes to exactly the input bytes.
#include "dp/pdu/dpv1.h"

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
  return 0;
}
