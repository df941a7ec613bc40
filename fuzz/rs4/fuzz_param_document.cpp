// libFuzzer target: the parameter document reader (rs4/param_doc/parameter_document.h),
// JSON text → RS4 parameter set. Invariants: never crash; a refusal has a code, a path
// starting with "$" and a reason; an accepted set passes the scanner's validate(), keeps the
// base's passwords and identity, and survives to_document → from_document unchanged.
#include "rs4/param_doc/parameter_document.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::rs4;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  static const scanner::ParameterSet kBase = scanner::factory_default();
  const auto result = param_doc::from_document(text, kBase);
  if (!result) {
    const auto& issue = result.issue;
    if (issue.path.empty() || issue.path[0] != '$' || issue.reason.empty()) std::abort();
    if (make_error_code(issue.error).message().empty()) std::abort();
    return 0;
  }
  const scanner::ParameterSet& set = *result.set;
  if (scanner::validate(set)) std::abort();
  if (set.passwords != kBase.passwords || set.identity != kBase.identity) std::abort();
  const auto again = param_doc::from_document(param_doc::to_document(set), kBase);
  if (!again || *again.set != set) std::abort();
  return 0;
}
