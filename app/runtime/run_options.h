#pragma once
// Option parsing of the device entries and demos (header-only): hexadecimal byte strings
// ("10 20", "1020", "0x10,0x20"), idents ("0x1234"), the generic slave configuration.
// Errors are UsageError with the reason.

#include "app/runtime/usage_error.h"
#include "dp/devices/generic_slave.h"

#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace rs4sim::app {

inline std::vector<std::uint8_t> parse_hex_bytes(const std::string& text, const std::string& what) {
  std::string digits;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '0' && i + 1 < text.size() && (text[i + 1] == 'x' || text[i + 1] == 'X')) {
      ++i;  // 0x prefix of one byte
      continue;
    }
    if (c == ' ' || c == ',' || c == ':' || c == '-') continue;
    if (!std::isxdigit(static_cast<unsigned char>(c))) {
      throw UsageError(what + ": '" + text +
                       "' is not hexadecimal (e.g. \"10 20\" or \"0x10,0x20\")");
    }
    digits += c;
  }
  if (digits.empty() || digits.size() % 2 != 0) {
    throw UsageError(what + ": '" + text + "' needs an even, non-zero number of hex digits");
  }
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < digits.size(); i += 2) {
    out.push_back(static_cast<std::uint8_t>(std::stoul(digits.substr(i, 2), nullptr, 16)));
  }
  return out;
}

inline std::uint16_t parse_ident(const std::string& text) {
  const bool is_hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
  const char* first = text.data() + (is_hex ? 2 : 0);
  const char* last = text.data() + text.size();
  unsigned value = 0;
  const auto [p, ec] = std::from_chars(first, last, value, is_hex ? 16 : 10);
  if (ec != std::errc{} || p != last || first == last || value > 0xFFFF) {
    throw UsageError("--ident: '" + text + "' is not a 16-bit Ident_Number (e.g. 0x1234)");
  }
  return static_cast<std::uint16_t>(value);
}

inline dp::devices::GenericSlaveConfig generic_slave_config(int address, const std::string& ident,
                                                            const std::string& cfg_hex) {
  if (address < 0 || address > 125) {
    throw UsageError("--address: " + std::to_string(address) +
                     " is outside 0..125 "
                     "([IEC 61158-4-3 addresses, SAPs])");
  }
  dp::devices::GenericSlaveConfig c{static_cast<std::uint8_t>(address), parse_ident(ident),
                                    parse_hex_bytes(cfg_hex, "--cfg"), true};
  try {
    dp::devices::GenericDevice probe({c.cfg});
  } catch (const std::system_error& e) {
    throw UsageError("--cfg " + cfg_hex + ": " + e.what() +
                     " (identifiers per "
                     "[IEC 61158-6-3 Chk_Cfg/Get_Cfg])");
  }
  return c;
}

inline std::string hex(std::span<const std::uint8_t> bytes) {
  std::string s;
  char buf[4];
  for (std::uint8_t b : bytes) {
    std::snprintf(buf, sizeof buf, "%02X", b);
    if (!s.empty()) s += ' ';
    s += buf;
  }
  return s;
}

}  // namespace rs4sim::app
