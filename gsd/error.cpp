#include "gsd/error.h"

namespace rs4sim::gsd {
namespace {

class Category final : public std::error_category {
 public:
  const char* name() const noexcept override { return "rs4sim.gsd"; }
  std::string message(int value) const override {
    switch (static_cast<ErrorCode>(value)) {
      case ErrorCode::kSyntax: return "GSD syntax error";
      case ErrorCode::kMissingHeader: return "GSD does not start with #Profibus_DP";
      case ErrorCode::kBlockStructure: return "GSD block structure error";
      case ErrorCode::kBadValue: return "GSD keyword has a malformed value";
      case ErrorCode::kOutOfRange: return "value out of range";
      case ErrorCode::kMissingKeyword: return "required GSD keyword missing";
      case ErrorCode::kDuplicate: return "defined twice";
      case ErrorCode::kUnknownReference: return "reference to an undefined entry";
      case ErrorCode::kBadCfg: return "malformed Cfg identifier";
      case ErrorCode::kUnknownModule: return "unknown module";
      case ErrorCode::kUnknownParameter: return "unknown parameter";
      case ErrorCode::kNotChangeable: return "parameter is not changeable";
      case ErrorCode::kPrmTooLong: return "User_Prm_Data too long";
      case ErrorCode::kFParameterLayout: return "F-parameter layout error";
      case ErrorCode::kModuleCount: return "wrong number of modules";
    }
    return "unknown GSD error";
  }
};

}  // namespace

const std::error_category& error_category() noexcept {
  static const Category category;
  return category;
}

std::error_code make_error_code(ErrorCode code) noexcept {
  return {static_cast<int>(code), error_category()};
}

std::string Error::what() const {
  std::string out;
  if (!file.empty()) out += file + ":";
  if (line > 0) out += std::to_string(line) + ":";
  if (!out.empty()) out += " ";
  out += message.empty() ? make_error_code(code).message() : message;
  if (!text.empty()) out += ": `" + text + "`";
  return out;
}

}  // namespace rs4sim::gsd
