// libFuzzer target: Chk_Cfg/Get_Cfg identifier decoder ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]).
// Every identifier re-encodes to exactly its bytes; the summary adds up the identifiers.
#include "dp/pdu/cfg.h"
#include "fuzz_check.h"

using namespace rs4sim::dp::pdu;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> du(data, size);
  for (const CfgService service : {CfgService::kChkCfg, CfgService::kGetCfg}) {
    const auto summary = summarize_cfg(du, service);
    std::span<const std::uint8_t> rest = du;
    CfgSummary sum;
    bool failed = false;
    while (!rest.empty()) {
      const auto p = decode_cfg_identifier(rest, service);
      if (!p) {
        failed = true;
        break;
      }
      const CfgParse& parse = p.value();
      fuzz::check(parse.size >= 1 && parse.size <= rest.size());
      fuzz::check(parse.identifier.encoded_size() == parse.size);
      rs4sim::dp::fdl::DataUnit out;
      fuzz::check(encode_cfg_identifier(parse.identifier, out).has_value());
      fuzz::check(fuzz::same(out, rest.first(parse.size)));
      ++sum.identifiers;
      sum.input_bytes += parse.identifier.input_bytes();
      sum.output_bytes += parse.identifier.output_bytes();
      rest = rest.subspan(parse.size);
    }
    if (summary) fuzz::check(!failed && summary.value() == sum);
  }
  return 0;
}
