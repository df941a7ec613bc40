// libFuzzer target: DPV1 MSAC_C2 decoders ([IEC 61158-6-3 MSAC_C2]). Initiate.req drops
// its reserved bytes 1..3, so the check is decode(encode(decode(x))) == decode(x).
#include "dp/pdu/dpv1_c2.h"
#include "fuzz_check.h"

using namespace rs4sim::dp::pdu;

namespace {

template <class Variant, class Decode>
void roundtrip(const Variant& v, Decode decode) {
  rs4sim::dp::fdl::DataUnit out;
  const auto r = std::visit([&](const auto& pdu) { return encode(pdu, out); }, v);
  fuzz::check(r.has_value());
  const auto again = decode(std::span<const std::uint8_t>(out.data(), out.size()));
  fuzz::check(again.has_value() && again.value() == v);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> du(data, size);
  if (const auto req = decode_c2_request(du)) {
    roundtrip(req.value(), [](auto s) { return decode_c2_request(s); });
  }
  if (const auto res = decode_c2_response(du)) {
    roundtrip(res.value(), [](auto s) { return decode_c2_response(s); });
  }
  if (const auto rm = decode_rm_response(du)) {
    rs4sim::dp::fdl::DataUnit out;
    fuzz::check(encode(rm.value(), out).has_value() && fuzz::same(out, du));
  }
  return 0;
}
