#include "rs4/scanner/identity_text.h"

#include <cstdio>

namespace rs4sim::rs4::scanner {

std::string device_type_text(std::uint16_t device_type) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%04X", static_cast<unsigned>(device_type));
  return text;
}

std::string serial_number_text(std::uint32_t serial_number) {
  return std::to_string(serial_number);
}

}  // namespace rs4sim::rs4::scanner
