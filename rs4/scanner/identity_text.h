#pragma once
// The device identity as every surface shows it (docs/archive-cli.md "Identity"): the archive
// CLI's tables, texts and JSON, the parameter summary and diff, the proxy's archive records.

#include <cstdint>
#include <string>

namespace rs4sim::rs4::scanner {

// "0x" and four upper-case hex digits: the 16-bit device type word of the IDENTIFY answer
// (docs/proxy-protocol.md), e.g. "0x0004".
std::string device_type_text(std::uint16_t device_type);

// Decimal, e.g. "74565".
std::string serial_number_text(std::uint32_t serial_number);

}  // namespace rs4sim::rs4::scanner
