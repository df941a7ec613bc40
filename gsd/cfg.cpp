// Cfg identifier decoding, [IEC 61158-6-3 Chk_Cfg/Get_Cfg] ([VPC3+ dp_if.h §3.1, §3.2],
// [CP 5613/5614 DP manual p. 204]).
#include "gsd/cfg.h"

#include <cstdio>
#include <string>

namespace rs4sim::gsd {
namespace {

Error cfg_error(std::size_t offset, const char* what) {
  char text[96];
  std::snprintf(text, sizeof text, "Cfg identifier at byte %zu: %s", offset, what);
  return Error{GsdError::kBadCfg, "", 0, "", text};
}

// Length byte of the special format: b7 consistency, b6 words, b5..0 length - 1.
void apply_length_byte(std::uint8_t b, std::size_t& bytes, bool& consistent) {
  const std::size_t unit = (b & 0x40U) != 0 ? 2 : 1;
  bytes = (static_cast<std::size_t>(b & 0x3FU) + 1) * unit;
  consistent = (b & 0x80U) != 0;
}

Result<CfgIdentifier> decode_one(std::span<const std::uint8_t> cfg, std::size_t offset) {
  CfgIdentifier id;
  id.offset = offset;
  const std::uint8_t b = cfg[offset];
  const unsigned direction = (b >> 4) & 0x3U;
  if (direction != 0) {  // compact ("general") identifier, 1 byte
    const std::size_t unit = (b & 0x40U) != 0 ? 2 : 1;
    const std::size_t bytes = (static_cast<std::size_t>(b & 0x0FU) + 1) * unit;
    const bool consistent = (b & 0x80U) != 0;
    if ((direction & 1U) != 0) id.input_bytes = bytes, id.input_consistent = consistent;
    if ((direction & 2U) != 0) id.output_bytes = bytes, id.output_consistent = consistent;
    return id;
  }
  // Special format: b7..6 which length bytes follow (output first), b3..0 manufacturer
  // bytes (15 = none, "skip the check", Chk_Cfg only).
  const unsigned lengths = (b >> 6) & 0x3U;
  std::size_t pos = offset + 1;
  if ((lengths & 2U) != 0) {
    if (pos >= cfg.size()) return cfg_error(offset, "output length byte missing");
    apply_length_byte(cfg[pos++], id.output_bytes, id.output_consistent);
  }
  if ((lengths & 1U) != 0) {
    if (pos >= cfg.size()) return cfg_error(offset, "input length byte missing");
    apply_length_byte(cfg[pos++], id.input_bytes, id.input_consistent);
  }
  const std::size_t manufacturer = b & 0x0FU;
  id.manufacturer_bytes = manufacturer == 15 ? 0 : manufacturer;
  if (cfg.size() - pos < id.manufacturer_bytes) {
    return cfg_error(offset, "manufacturer-specific bytes missing");
  }
  id.size = pos + id.manufacturer_bytes - offset;
  return id;
}

}  // namespace

Result<CfgLayout> decode_cfg(std::span<const std::uint8_t> cfg) {
  if (cfg.empty()) return Error{GsdError::kBadCfg, "", 0, "", "Cfg data is empty"};
  CfgLayout layout;
  for (std::size_t offset = 0; offset < cfg.size();) {
    RS4SIM_GSD_TRY(auto id, decode_one(cfg, offset));
    layout.input_bytes += id.input_bytes;
    layout.output_bytes += id.output_bytes;
    offset += id.size;
    layout.identifiers.push_back(id);
  }
  return layout;
}

}  // namespace rs4sim::gsd
