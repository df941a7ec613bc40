// libFuzzer target: Set_Prm decoder ([IEC 61158-6-3 Set_Prm, DPV1_Status]). Reserved bits are
// preserved, so a decoded Set_Prm must re-encode to exactly the input bytes. The user
// data is also read as structured blocks ([IEC 61158-6-3 structured Prm_Data]); each block
// re-encodes to its bytes.
#include "dp/pdu/prm_blocks.h"
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
    const auto& user = r.value().user_data;
    PrmBlockReader reader(std::span<const std::uint8_t>(user.data(), user.size()));
    for (std::size_t i = 0; i <= user.size(); ++i) {
      const auto b = reader.next();
      if (!b || !b.value()) break;
      const PrmBlock& blk = *b.value();
      rs4sim::dp::fdl::DataUnit one;
      fuzz::check(encode_prm_block(blk.type, blk.slot, blk.index, blk.data, one).has_value());
      fuzz::check(fuzz::same(one, blk.raw));
    }
  }
  return 0;
}
