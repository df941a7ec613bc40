// The linear structure scan (structure.h): one pass, a counter of open brackets and the kind
// of the innermost one; no recursion, so no depth can exhaust the stack.
#include "json/structure.h"

#include <string>
#include <vector>

namespace rs4sim::json {
namespace {

// The offset just past the string that opens at `at` (text.size() when it never closes).
std::size_t skip_string(std::string_view text, std::size_t at) {
  for (std::size_t i = at + 1; i < text.size(); ++i) {
    if (text[i] == '\\') {
      ++i;  // the escaped character, whatever it is
    } else if (text[i] == '"') {
      return i + 1;
    }
  }
  return text.size();
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::optional<SyntaxError> first_structure_error(std::string_view text, StructureRules rules) {
  // open[k]: true when the bracket open at depth k is '[' (the kinds of the open ones only:
  // never more than max_depth + 1 entries).
  std::vector<bool> open;
  bool first_in_array = false;  // the previous token opened an array (only space since)
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (is_space(c)) {
      ++i;
      continue;
    }
    if (c == '"') {
      i = skip_string(text, i);
      first_in_array = false;
      continue;
    }
    if (c == '[' || c == '{') {
      if (static_cast<int>(open.size()) > rules.max_depth) {
        return SyntaxError{i, "nested deeper than " + std::to_string(rules.max_depth)};
      }
      if (c == '[' && first_in_array && !rules.arrays_in_arrays) {
        return SyntaxError{i, "an array directly inside an array (this format has none)"};
      }
      open.push_back(c == '[');
    } else if ((c == ']' || c == '}') && !open.empty()) {
      open.pop_back();
    }
    // After ',' inside an array the next element is again "directly in the array".
    first_in_array = (c == '[') || (c == ',' && !open.empty() && open.back());
    ++i;
  }
  return std::nullopt;
}

}  // namespace rs4sim::json
