#pragma once
// Chk_Cfg / Get_Cfg identifiers ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]): what a module's Cfg bytes say
// about its input and output lengths. The GSD module needs this to fill the slave
// configuration; it does not depend on dp/, so it carries its own small decoder.

#include "gsd/error.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::gsd {

struct CfgIdentifier {
  std::size_t offset = 0;  // of the identifier byte in the Cfg data
  std::size_t size = 1;    // identifier + length bytes + manufacturer bytes
  std::size_t input_bytes = 0;
  std::size_t output_bytes = 0;
  bool input_consistent = false;  // consistency over the whole length
  bool output_consistent = false;
  std::size_t manufacturer_bytes = 0;
};

struct CfgLayout {
  std::vector<CfgIdentifier> identifiers;
  std::size_t input_bytes = 0;
  std::size_t output_bytes = 0;
};

// Errors (GsdError::kBadCfg, the message names the identifier's offset): empty data,
// a length byte or manufacturer-specific bytes missing at the end. Manufacturer count
// 15 ("no manufacturer data, skip the check", Chk_Cfg) is accepted as 0 bytes.
Result<CfgLayout> decode_cfg(std::span<const std::uint8_t> cfg);

}  // namespace rs4sim::gsd
