// The structure of JSON text checked in one linear pass before any parser builds a value:
// how deep it nests and whether an array holds an array. protobuf's JSON parser (3.21) takes
// time quadratic in the nesting before its own recursion limit refuses a text (10,000 levels
// 1.4 s, 100,000 more than a minute), and it flattens an array inside an array of a message's
// repeated field ("stations": [[]] reads as no station). This scan needs no memory beyond the
// open brackets it counts (at most the limit) and stops at the first refusal.
#pragma once

#include "json/syntax.h"

#include <cstddef>
#include <optional>
#include <string_view>

namespace rs4sim::json {

// protobuf's recursion limit, and json/syntax.h's: the top value is at depth 0, what an
// array or object at depth d holds is at depth d + 1.
inline constexpr int kMaxDepth = 100;

struct StructureRules {
  int max_depth = kMaxDepth;    // an object or array opened at a depth beyond it is refused
  bool arrays_in_arrays = true;  // false: "[[" (with space between) is refused
};

// The first refusal: the offset of the bracket that opens too deep ("nested deeper than
// 100") or of the array that stands directly inside an array; nothing when neither occurs.
// Strings are skipped (brackets in them count for nothing); the grammar is not checked (an
// unterminated string ends the scan without a refusal; first_syntax_error finds it).
std::optional<SyntaxError> first_structure_error(std::string_view text, StructureRules rules = {});

}  // namespace rs4sim::json
