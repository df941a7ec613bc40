// json::first_structure_error, json::to_message, json::cut and json::offset_of_member on
// hand-written texts; every offset is counted by hand in the comment beside it (byte 0 first).
#include "json/locate.h"
#include "json/message.h"
#include "json/structure.h"

#include <google/protobuf/struct.pb.h>

#include <gtest/gtest.h>

#include <string>

namespace rs4sim::json {
namespace {

std::string refusal_of(std::string_view text, StructureRules rules = {}) {
  const auto e = first_structure_error(text, rules);
  if (!e) return "none";
  return std::to_string(e->offset) + " " + e->reason;
}

// n arrays in each other around `inner`.
std::string nested(std::size_t n, std::string_view inner = "") {
  return std::string(n, '[') + std::string(inner) + std::string(n, ']');
}

TEST(JsonStructure, DepthAsTheGrammarScannerCountsIt) {
  // The top value is at depth 0; the k-th bracket (offset k - 1) opens a value at depth k - 1.
  // 101 brackets: the last opens at depth 100, allowed; the 102nd (offset 101) at depth 101.
  EXPECT_EQ(refusal_of(nested(101)), "none");
  EXPECT_EQ(refusal_of(nested(102)), "101 nested deeper than 100");
  EXPECT_EQ(refusal_of(std::string(50'000, '[')), "101 nested deeper than 100");
  // Objects count as arrays do: {"a": at offsets 0-4, then [ at 6 ... ; the 102nd bracket of
  // "{\"a\":" + 101 '[' is the 101st '[', at offset 5 + 100 = 105.
  EXPECT_EQ(refusal_of("{\"a\":" + nested(101) + "}"), "105 nested deeper than 100");
  // A limit of 2: brackets at offsets 0, 1, 2 open depths 0, 1, 2; offset 3 opens depth 3.
  EXPECT_EQ(refusal_of(nested(3), {2, true}), "none");
  EXPECT_EQ(refusal_of(nested(4), {2, true}), "3 nested deeper than 2");
}

TEST(JsonStructure, BracketsInStringsCountForNothing) {
  EXPECT_EQ(refusal_of("\"" + std::string(500, '[') + "\""), "none");
  // An escaped quote does not end the string: "\"[[[[" is one string.
  EXPECT_EQ(refusal_of("[\"\\\"" + std::string(200, '[') + "\"]"), "none");
  // An unterminated string ends the scan (the grammar scanner names it).
  EXPECT_EQ(refusal_of("[\"" + std::string(200, '[')), "none");
}

TEST(JsonStructure, ArraysInArraysWhenTheFormatHasNone) {
  const StructureRules none{kMaxDepth, false};
  // { 0, "stations" 1-10, : 11, [ 12, [ 13
  EXPECT_EQ(refusal_of(R"({"stations":[[]]})", none),
            "13 an array directly inside an array (this format has none)");
  // [ 0, { 1, } 2, , 3, space 4, [ 5: a later element counts too
  EXPECT_EQ(refusal_of("[{}, []]", none),
            "5 an array directly inside an array (this format has none)");
  // [ 0, space 1, newline 2, space 3, [ 4
  EXPECT_EQ(refusal_of("[ \n [1]]", none),
            "4 an array directly inside an array (this format has none)");
  EXPECT_EQ(refusal_of(R"([{"a": []}, 1, "[["])", none), "none");  // in an object: fine
  EXPECT_EQ(refusal_of(R"({"stations":[[]]})"), "none");               // allowed by default
}

TEST(JsonToMessage, StructureRefusalNamesLineAndColumnBeforeProtobufSeesTheText) {
  google::protobuf::Value v;
  // 100 KB, 50,000 deep: the refusal names the 102nd bracket, line 1 column 102.
  const auto deep = std::string(50'000, '[') + std::string(50'000, ']');
  const auto status = to_message(deep, v, {});
  EXPECT_FALSE(status.ok());
  EXPECT_EQ(std::string(status.message()), "1:102: nested deeper than 100");
  EXPECT_TRUE(to_message(nested(50, "1"), v, {}).ok());
  // Line 2 column 1 for an array of arrays on the second line.
  const auto flat = to_message("[\n[]]", v, {}, {kMaxDepth, false});
  EXPECT_EQ(std::string(flat.message()), "2:1: an array directly inside an array (this format has none)");
}

TEST(JsonToMessage, ProtobufsOwnRefusalIsCutShort) {
  google::protobuf::Value v;
  // Duplicate keys pass the structure scan; protobuf refuses and may quote what it saw.
  const auto status = to_message("{\"a\": 1, \"a\": 2}", v, {});
  EXPECT_FALSE(status.ok());
  google::protobuf::ListValue list;
  const auto long_value = "{\"values\": \"" + std::string(1'000'000, 'x') + "\"}";
  const auto refused = to_message(long_value, list, {});
  EXPECT_FALSE(refused.ok());
  EXPECT_LE(refused.message().size(), kMessageLimit + 40);
}

TEST(JsonCut, KeepsShortTextAndCutsLongTextAtACharacter) {
  EXPECT_EQ(cut("abc", 3), "abc");
  EXPECT_EQ(cut("abcd", 3), "abc\xE2\x80\xA6 (4 bytes)");
  // a 0, é 1-2 (C3 A9): a cut at 2 would split é, so it keeps "a"
  EXPECT_EQ(cut("a\xC3\xA9z", 2), "a\xE2\x80\xA6 (4 bytes)");
  EXPECT_EQ(cut(std::string(10'000'000, 'v')).size(), kMessageLimit + 3 + 17);  // "… (10000000 bytes)"
}

TEST(JsonLocate, FindsAMemberByPathAndByItsCamelCaseName) {
  // { 0, "a" 1-3, : 4, [ 5, 1 6, , 7, { 8, "stored_at" .. : the value "x" at 22
  //                         "storedAt" 9-18, : 19, space 20, " 21? counted below
  const std::string t = R"({"a":[1,{"storedAt": "x"}],"b":{"c":true}})";
  // { 0 "a" 1-3 : 4 [ 5 1 6 , 7 { 8 "storedAt" 9-18 : 19 space 20 "x" 21-23 } 24 ] 25 , 26
  // "b" 27-29 : 30 { 31 "c" 32-34 : 35 true 36-39
  EXPECT_EQ(offset_of_member(t, "a"), 5u);
  EXPECT_EQ(offset_of_member(t, "a[0]"), 6u);
  EXPECT_EQ(offset_of_member(t, "a[1].stored_at"), 21u);
  EXPECT_EQ(offset_of_member(t, "a[1].storedAt"), 21u);
  EXPECT_EQ(offset_of_member(t, "b.c"), 36u);
  EXPECT_EQ(offset_of_member(t, "a[2]"), std::nullopt);
  EXPECT_EQ(offset_of_member(t, "b.d"), std::nullopt);
  EXPECT_EQ(offset_of_member(t, "a.b"), std::nullopt);  // a is an array
}

}  // namespace
}  // namespace rs4sim::json
