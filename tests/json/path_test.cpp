// json::member_path and json::string_literal, checked against paths written out by hand: a
// plain key joins with '.', every other key (empty, a space, a dot, a quote, a control
// character) is bracketed as a JSON string, so a message never names an empty or ambiguous
// place.
#include "json/path.h"

#include <gtest/gtest.h>

#include <string>

namespace rs4sim::json {
namespace {

TEST(JsonPath, PlainKeysJoinWithADot) {
  EXPECT_EQ(member_path("$", "stations"), "$.stations");
  EXPECT_EQ(member_path("$.stations[2]", "boot-time"), "$.stations[2].boot-time");
  EXPECT_EQ(member_path("", "frame_start"), "frame_start");
  EXPECT_EQ(member_path("reply", "fields"), "reply.fields");
}

TEST(JsonPath, OtherKeysAreBracketedJsonStrings) {
  // The empty key: the fuzzer's find (a wire table with "" as a key named no place at all).
  EXPECT_EQ(member_path("", ""), R"([""])");
  EXPECT_EQ(member_path("$", ""), R"($[""])");
  EXPECT_EQ(member_path("$", "a b"), R"($["a b"])");
  EXPECT_EQ(member_path("$", "a.b"), R"($["a.b"])");  // not $.a.b, which would be two levels
  EXPECT_EQ(member_path("reply", "say \"hi\""), R"(reply["say \"hi\""])");
  EXPECT_EQ(member_path("$", "back\\slash"), R"($["back\\slash"])");
}

TEST(JsonPath, ControlCharactersAreEscapedSoThePathStaysOneLine) {
  EXPECT_EQ(string_literal("a\nb\tc"), R"("a\nb\tc")");
  EXPECT_EQ(string_literal(std::string("\0", 1)), R"("\u0000")");
  EXPECT_EQ(string_literal("\x1f\r"), R"("\u001f\u000d")");
  EXPECT_EQ(string_literal("\x7f"), "\"\x7f\"");  // DEL needs no escape [RFC 8259 §7]
  // UTF-8 passes unchanged: "Départ" (0xC3 0xA9 for é).
  EXPECT_EQ(string_literal("D\xC3\xA9part"), "\"D\xC3\xA9part\"");
}

}  // namespace
}  // namespace rs4sim::json
