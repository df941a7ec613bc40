#include "gsd/model.h"

#include "gsd/syntax.h"

#include <algorithm>

namespace rs4sim::gsd {

std::string_view to_string(ParamType type) {
  switch (type) {
    case ParamType::kBit: return "Bit";
    case ParamType::kBitArea: return "BitArea";
    case ParamType::kUnsigned8: return "Unsigned8";
    case ParamType::kUnsigned16: return "Unsigned16";
    case ParamType::kUnsigned32: return "Unsigned32";
    case ParamType::kSigned8: return "Signed8";
    case ParamType::kSigned16: return "Signed16";
    case ParamType::kSigned32: return "Signed32";
  }
  return "?";
}

std::size_t byte_size(ParamType type) {
  switch (type) {
    case ParamType::kUnsigned16:
    case ParamType::kSigned16: return 2;
    case ParamType::kUnsigned32:
    case ParamType::kSigned32: return 4;
    default: return 1;
  }
}

bool ExtParam::accepts(std::int64_t value) const {
  if (!allowed.empty()) return std::find(allowed.begin(), allowed.end(), value) != allowed.end();
  return value >= min && value <= max;
}

std::string ExtParam::range_text() const {
  if (allowed.empty()) return std::to_string(min) + ".." + std::to_string(max);
  std::string out;
  for (const auto v : allowed) out += (out.empty() ? "" : ", ") + std::to_string(v);
  return out;
}

std::string_view trim_blanks(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

const Module* Device::find_module(std::string_view name) const {
  for (const auto& m : modules) {
    if (syntax::iequals(m.name, name)) return &m;
  }
  const std::string_view wanted = trim_blanks(name);
  for (const auto& m : modules) {
    if (syntax::iequals(trim_blanks(m.name), wanted)) return &m;
  }
  return nullptr;
}

const Module* Device::find_module_by_reference(std::uint32_t reference) const {
  for (const auto& m : modules) {
    if (m.reference == reference) return &m;
  }
  return nullptr;
}

const BaudRate* Device::find_baud(std::uint32_t bits_per_second) const {
  for (const auto& b : baud_rates) {
    if (b.bits_per_second == bits_per_second) return &b;
  }
  return nullptr;
}

}  // namespace rs4sim::gsd
