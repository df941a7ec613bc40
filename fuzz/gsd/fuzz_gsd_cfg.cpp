// libFuzzer: Chk_Cfg bytes → gsd::decode_cfg ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]). The identifiers
// found must tile the input exactly.
#include "gsd/cfg.h"

#include <cstddef>
#include <cstdint>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  auto layout = rs4sim::gsd::decode_cfg(std::span<const std::uint8_t>(data, size));
  if (!layout) return 0;
  std::size_t next = 0;
  for (const auto& id : layout.value().identifiers) {
    if (id.offset != next || id.size == 0) __builtin_trap();
    next += id.size;
  }
  if (next != size) __builtin_trap();
  return 0;
}
