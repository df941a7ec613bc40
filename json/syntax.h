// Where JSON text first breaks the grammar of RFC 8259, to name its line and column in a
// message: protobuf's JSON parser says what it did not expect but not where in a multi-line
// file. A scanner only: it builds no value (protobuf's parser does that).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rs4sim::json {

// The first break of the grammar: the byte offset where the scanner stopped (the start of an
// unterminated string; text.size() when the text ended too early) and what it expected there.
struct SyntaxError {
  std::size_t offset = 0;
  std::string reason;  // "expected ':' after the key", "a string without its closing quote", ...
};

// The first break of `text`, or nothing when it is one JSON value (with white space around).
// Nesting deeper than 100 (protobuf's recursion limit) is a break. A text without a break may
// still be refused by protobuf (a number beyond double, a duplicate key).
std::optional<SyntaxError> first_syntax_error(std::string_view text);

// "3:17" for a byte offset into text: line and column (of bytes), both from 1. An offset past
// the end counts as the end.
std::string line_column(std::string_view text, std::size_t offset);

}  // namespace rs4sim::json
