#pragma once
// Helpers for the GSD tests: read corpus files, build small GSD texts.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

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

}  // namespace rs4sim::gsd::testing
