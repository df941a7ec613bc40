#pragma once
// Errors of the GSD module: a typed code (std::error_code, category "rs4sim.gsd") plus
// the context an engineer needs to fix the file or the command: file name, line number
// (1-based; 0 = not tied to a line) and the offending text.

#include "codec/error_category.h"

#include <boost/outcome/result.hpp>

#include <string>
#include <string_view>
#include <system_error>
#include <utility>

namespace rs4sim::gsd {

enum class GsdError {
  kSyntax = 1,        // malformed token or line (unterminated string, stray character)
  kMissingHeader,     // the first keyword line is not #Profibus_DP
  kBlockStructure,    // End… without its block, nested block, block not closed
  kBadValue,          // a keyword has the wrong kind or number of values
  kOutOfRange,        // a value outside what the keyword or parameter allows
  kMissingKeyword,    // a required keyword is absent (e.g. Ident_Number)
  kDuplicate,         // a keyword, parameter number or module defined twice
  kUnknownReference,  // Ext_User_Prm_Data_Ref / Prm_Text_Ref to nothing
  kBadCfg,            // a module's Cfg identifiers do not decode ([IEC 61158-6-3 Chk_Cfg/Get_Cfg])
  kUnknownModule,     // configuration names a module the GSD does not have
  kUnknownParameter,  // override names no parameter of the configuration
  kNotChangeable,     // override of a parameter with Changeable = 0 (or F_Par_CRC)
  kPrmTooLong,        // User_Prm_Data longer than Max_User_Prm_Data_Len / 237
  kFParameterLayout,  // F-parameters not laid out as the PROFIsafe block
  kModuleCount,       // wrong number of modules for the station type
};

[[nodiscard]] std::string_view to_string(GsdError code) noexcept;
constexpr const char* error_category_name(GsdError) noexcept { return "rs4sim.gsd"; }
inline std::error_code make_error_code(GsdError code) noexcept {
  return codec::make_error_code_of(code);
}

struct Error {
  GsdError code = GsdError::kSyntax;
  std::string file;     // file name as given to parse(), may be empty
  int line = 0;         // 1-based line of the statement; 0 = not tied to a line
  std::string text;     // offending text (statement or value), may be empty
  std::string message;  // what is wrong, e.g. "F_WD_Time = 5 is out of range 10..1000"

  std::error_code error_code() const noexcept { return make_error_code(code); }
  // "file:line: message: `text`" (parts left out when empty)
  std::string what() const;
};

// Something the interpreter skipped, e.g. a word that is not a GSD keyword (engineering tools
// skip those too): "file:line: message: `text`".
struct Warning {
  std::string file;
  int line = 0;
  std::string text;
  std::string message;
  std::string what() const;
};

template <class T>
using Result = boost::outcome_v2::result<T, Error, boost::outcome_v2::policy::terminate>;

}  // namespace rs4sim::gsd

// Early return on error (Boost 1.74's BOOST_OUTCOME_TRY cannot assign to an existing
// variable). RS4SIM_GSD_TRY(decl_or_lvalue, expr); RS4SIM_GSD_TRYV(expr) for Result<void>.
#define RS4SIM_GSD_CONCAT_(a, b) a##b
#define RS4SIM_GSD_CONCAT(a, b) RS4SIM_GSD_CONCAT_(a, b)
#define RS4SIM_GSD_TRY_(tmp, decl, ...)    \
  auto&& tmp = (__VA_ARGS__);              \
  if (!tmp) return std::move(tmp).error(); \
  decl = std::move(tmp).value()
#define RS4SIM_GSD_TRY(decl, ...) \
  RS4SIM_GSD_TRY_(RS4SIM_GSD_CONCAT(rs4sim_gsd_try_, __LINE__), decl, __VA_ARGS__)
#define RS4SIM_GSD_TRYV(...)                                         \
  do {                                                               \
    auto&& rs4sim_gsd_tryv = (__VA_ARGS__);                          \
    if (!rs4sim_gsd_tryv) return std::move(rs4sim_gsd_tryv).error(); \
  } while (0)

template <>
struct std::is_error_code_enum<rs4sim::gsd::GsdError> : std::true_type {};
