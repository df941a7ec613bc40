// json::first_syntax_error and json::line_column on hand-written texts. Every offset is
// counted by hand in the comment beside it (byte 0 is the first), every line:column from it.
#include "json/syntax.h"

#include <gtest/gtest.h>

#include <string>

namespace rs4sim::json {
namespace {

// "offset line:column reason" of the first break, or "none".
std::string break_of(std::string_view text) {
  const auto e = first_syntax_error(text);
  if (!e) return "none";
  return std::to_string(e->offset) + " " + line_column(text, e->offset) + " " + e->reason;
}

TEST(JsonSyntax, AcceptsJsonWithEveryKindAndWhiteSpace) {
  EXPECT_EQ(break_of(R"({"a": [1, -0.5e+3, 0, 2E-7, "x\u00e9\n\"\\\/", true, false, null, {}, []]})"),
            "none");
  EXPECT_EQ(break_of(" \t\r\n 0 \n"), "none");
  EXPECT_EQ(break_of(R"("")"), "none");
  EXPECT_EQ(break_of("\"\xC3\xA9\""), "none");  // UTF-8 é inside a string
}

TEST(JsonSyntax, ObjectBreaks) {
  // { 0, "a" 1-3, : 4, space 5, 1 6, space 7, " 8
  EXPECT_EQ(break_of(R"({"a": 1 "b": 2})"), "8 1:9 expected ',' or '}' after an object member");
  // { 0, "a" 1-3, space 4, 1 5
  EXPECT_EQ(break_of(R"({"a" 1})"), "5 1:6 expected ':' after the key");
  // { 0, a 1
  EXPECT_EQ(break_of("{a: 1}"), "1 1:2 expected a key in double quotes");
  // { 0, "a" 1-3, : 4, 1 5, , 6, } 7: a trailing comma wants another key
  EXPECT_EQ(break_of(R"({"a":1,})"), "7 1:8 expected a key in double quotes");
  // { 0, the end at 1
  EXPECT_EQ(break_of("{"), "1 1:2 expected a key in double quotes");
}

TEST(JsonSyntax, ArrayBreaksOnALaterLine) {
  // line 1 "{\n" is bytes 0-1; line 2 starts at 2: spaces 2-3, "a" 4-6, : 7, space 8, [ 9,
  // 1 10, , 11, space 12, 2 13, , 14, ] 15 (column 15 - 2 + 1 = 14)
  EXPECT_EQ(break_of("{\n  \"a\": [1, 2,]\n}"), "15 2:14 expected a value");
  // [ 0, 1 1, space 2, 2 3, the end at 4
  EXPECT_EQ(break_of("[1 2"), "3 1:4 expected ',' or ']' after an array element");
  EXPECT_EQ(break_of("[1,"), "3 1:4 expected a value, found the end of the text");
}

TEST(JsonSyntax, ValueAndNumberBreaks) {
  EXPECT_EQ(break_of(""), "0 1:1 expected a value, found the end of the text");
  EXPECT_EQ(break_of("   "), "3 1:4 expected a value, found the end of the text");
  EXPECT_EQ(break_of("tru"), "0 1:1 expected a value");
  EXPECT_EQ(break_of("nul"), "0 1:1 expected a value");
  EXPECT_EQ(break_of("x"), "0 1:1 expected a value");
  EXPECT_EQ(break_of("-"), "1 1:2 expected a digit");     // - 0, nothing at 1
  EXPECT_EQ(break_of("1."), "2 1:3 expected a digit");    // 1 0, . 1
  EXPECT_EQ(break_of("1e+"), "3 1:4 expected a digit");   // 1 0, e 1, + 2
  EXPECT_EQ(break_of("-a"), "1 1:2 expected a digit");
  // 0 0, then 1 at offset 1 is text after the value (no leading zeros)
  EXPECT_EQ(break_of("01"), "1 1:2 text after the end of the JSON value");
  // [ 0, 1 1, ] 2, space 3, x 4
  EXPECT_EQ(break_of("[1] x"), "4 1:5 text after the end of the JSON value");
  // "é" is bytes 0-3 (é is two bytes); space 4, x 5: columns count bytes
  EXPECT_EQ(break_of("\"\xC3\xA9\" x"), "5 1:6 text after the end of the JSON value");
}

TEST(JsonSyntax, StringBreaks) {
  // [ 0, " 1: an unterminated string is placed at its opening quote
  EXPECT_EQ(break_of(R"(["abc)"), "1 1:2 a string without its closing quote");
  EXPECT_EQ(break_of("\"ab\\"), "0 1:1 a string without its closing quote");  // ends after '\'
  // " 0, \ 1, q 2
  EXPECT_EQ(break_of(R"("\q")"), "2 1:3 an unknown escape in a string");
  // " 0, \ 1, u 2 (where the break is placed), 1 3, 2 4, G 5
  EXPECT_EQ(break_of(R"("\u12G4")"), "2 1:3 expected four hex digits after \\u");
  EXPECT_EQ(break_of(R"("\u12)"), "2 1:3 expected four hex digits after \\u");
  // " 0, a 1, tab 2
  EXPECT_EQ(break_of("\"a\tb\""), "2 1:3 a control character in a string (write it escaped)");
}

TEST(JsonSyntax, NestingDeeperThan100) {
  // The top value is at depth 0, what the array at offset k holds at depth k + 1. 101 arrays
  // in each other are fine while the innermost is empty (it holds no value at depth 101);
  // a value at offset 101, inside the 101st array, is at depth 101.
  EXPECT_EQ(break_of(std::string(101, '[') + std::string(101, ']')), "none");
  EXPECT_EQ(break_of(std::string(100, '[') + "1" + std::string(100, ']')), "none");
  EXPECT_EQ(break_of(std::string(101, '[') + "1" + std::string(101, ']')),
            "101 1:102 nested deeper than 100");
  EXPECT_EQ(break_of(std::string(102, '[') + std::string(102, ']')),
            "101 1:102 nested deeper than 100");
}

TEST(JsonLineColumn, CountsLinesAndBytesFromOne) {
  const std::string_view t = "ab\ncd\n";  // a 0, b 1, \n 2, c 3, d 4, \n 5
  EXPECT_EQ(line_column(t, 0), "1:1");
  EXPECT_EQ(line_column(t, 2), "1:3");  // the newline ends its line
  EXPECT_EQ(line_column(t, 3), "2:1");
  EXPECT_EQ(line_column(t, 4), "2:2");
  EXPECT_EQ(line_column(t, 6), "3:1");  // the end, after the last newline
  EXPECT_EQ(line_column(t, 100), "3:1");  // past the end counts as the end
  EXPECT_EQ(line_column("", 0), "1:1");
  EXPECT_EQ(line_column("a\r\nb", 1), "1:2");  // \r is a byte of line 1
  EXPECT_EQ(line_column("a\r\nb", 3), "2:1");
}

}  // namespace
}  // namespace rs4sim::json
