#pragma once
// `rs4sim gsd check FILE` (docs/gsd.md "Checking a file"): what rs4sim reads from a GSD, for an
// engineer to compare with the engineering tool: ident, rates with MaxTsdr, the station, every
// module with its Cfg bytes and I/O sizes (presets marked), the SlotDefinition slots, the default
// configuration (gsd::configure with no module named), the parameters with defaults and ranges,
// the F-parameter blocks, and every warning with file:line.

#include "gsd/model.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rs4sim::gsd {

std::string check_report(const Device& device);

// "C0 84 84" and "0x5234", as the reports print them.
std::string hex_bytes(const std::vector<std::uint8_t>& bytes);
std::string hex16(unsigned v);

}  // namespace rs4sim::gsd
