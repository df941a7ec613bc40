#pragma once
// Helpers for the GSD tests: read corpus files, build small GSD texts.
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rs4sim::gsd::testing {

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string corpus(const std::string& name) {
  return read_file(std::string(RS4SIM_GSD_CORPUS) + "/" + name);
}

// A minimal valid header + baud part, so error tests can focus on one line.
inline std::string minimal(const std::string& rest) {
  return "#Profibus_DP\nIdent_Number = 0x1234\n12M_supp = 1\nMaxTsdr_12M = 800\n" + rest;
}

// CRC1 of [IEC 61784-3-3 CRC1] written here as a reference: CRC-16 poly 0x4EAB, preset 0,
// MSB first, no reflection, no final XOR.
inline std::uint16_t reference_crc1(const std::vector<std::uint8_t>& bytes) {
  std::uint16_t crc = 0;
  for (const auto b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ (b << 8));
    for (int i = 0; i < 8; ++i) {
      crc = static_cast<std::uint16_t>((crc & 0x8000U) != 0 ? (crc << 1) ^ 0x4EAB : crc << 1);
    }
  }
  return crc;
}

}  // namespace rs4sim::gsd::testing
