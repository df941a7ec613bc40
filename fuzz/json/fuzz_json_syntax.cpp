// libFuzzer target: the JSON grammar scanner (json/syntax.h), the input as JSON text.
// Invariants: no crash or hang; a break lies inside the text (or at its end) with a reason,
// and line_column() names a line and column from 1 that agree with the newlines before it;
// a text without a break gets one more break, "text after the end of the JSON value", where
// an x appended after a space stands.
#include "json/syntax.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::json;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto e = first_syntax_error(text);
  if (!e) {
    const std::string more = std::string(text) + " x";
    const auto after = first_syntax_error(more);
    if (!after || after->offset != size + 1 ||
        after->reason != "text after the end of the JSON value")
      std::abort();
    return 0;
  }
  if (e->offset > size || e->reason.empty()) std::abort();
  const auto before = text.substr(0, e->offset);
  const auto newlines = static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  const auto nl = before.rfind('\n');
  const auto column = nl == std::string_view::npos ? e->offset + 1 : e->offset - nl;
  if (line_column(text, e->offset) != std::to_string(newlines + 1) + ":" + std::to_string(column))
    std::abort();
  return 0;
}
