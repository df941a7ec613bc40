#include "gsd/error.h"

#include <cstdio>

namespace rs4sim::gsd {
namespace {

// The offending text as a terminal shows it: control bytes of a binary file as \xNN, cut after
// 120 bytes (at a character boundary).
std::string shown(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto b = static_cast<unsigned char>(c);
    if (out.size() >= 120 && (b & 0xC0U) != 0x80U) return out + "…";  // not inside a character
    if ((b < 0x20 && c != '\t') || b == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", b);
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string_view to_string(GsdError e) noexcept {
  switch (e) {
    case GsdError::kSyntax: return "GSD syntax error";
    case GsdError::kMissingHeader: return "GSD does not start with #Profibus_DP";
    case GsdError::kBlockStructure: return "GSD block structure error";
    case GsdError::kBadValue: return "GSD keyword has a malformed value";
    case GsdError::kOutOfRange: return "value out of range";
    case GsdError::kMissingKeyword: return "required GSD keyword missing";
    case GsdError::kDuplicate: return "defined twice";
    case GsdError::kUnknownReference: return "reference to an undefined entry";
    case GsdError::kBadCfg: return "malformed Cfg identifier";
    case GsdError::kUnknownModule: return "unknown module";
    case GsdError::kUnknownParameter: return "unknown parameter";
    case GsdError::kNotChangeable: return "parameter is not changeable";
    case GsdError::kPrmTooLong: return "User_Prm_Data too long";
    case GsdError::kFParameterLayout: return "F-parameter layout error";
    case GsdError::kModuleCount: return "wrong number of modules";
  }
  return "unknown GSD error";
}

std::string Error::what() const {
  std::string out;
  if (!file.empty()) out += file + ":";
  if (line > 0) out += std::to_string(line) + ":";
  if (!out.empty()) out += " ";
  out += message.empty() ? make_error_code(code).message() : message;
  if (!text.empty()) out += ": `" + shown(text) + "`";
  return out;
}

std::string Warning::what() const {
  return Error{GsdError::kSyntax, file, line, text, message}.what();
}

}  // namespace rs4sim::gsd
