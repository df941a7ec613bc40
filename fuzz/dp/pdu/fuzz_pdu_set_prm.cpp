// libFuzzer target: Set_Prm decoder (spec/profibus-dp.md §2.3, §3.1). Reserved bits are
// preserved, so a decoded Set_Prm must re-encode to exactly the input bytes.
#include "dp/pdu/set_prm.h"

#include "fuzz_check.h"

using namespace rs4sim::dp::pdu;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> du(data, size);
  for (const PrmLayout layout : {PrmLayout::kDpv0, PrmLayout::kDpv1}) {
    const auto r = decode_set_prm(du, layout);
    if (!r) continue;
    rs4sim::dp::fdl::DataUnit out;
    fuzz::check(encode_set_prm(r.value(), out).has_value());
    fuzz::check(fuzz::same(out, du));
    (void)r.value().watchdog_time();
    if (r.value().dpv1) fuzz::check(r.value().dpv1->max_outstanding_alarms() <= 32);
  }
  return 0;
}
