// GSD syntax ([PROFIBUS GSD spec syntax]): logical lines, statements, values and blocks.
#include "gsd/syntax.h"

#include "test_util.h"

#include <gtest/gtest.h>

namespace rs4sim::gsd::syntax {
namespace {

Statement one(const std::string& line) {
  auto st = parse_statement({7, line}, "t.gsd");
  EXPECT_TRUE(st) << (st ? "" : st.error().what());
  return st ? st.value() : Statement{};
}

TEST(GsdLexer, CommentsAndBlankLinesVanish) {
  auto lines = split_logical_lines("; comment\n\n  \t\nA = 1 ; trailing\n;x\nB = 2", "f");
  ASSERT_TRUE(lines);
  ASSERT_EQ(lines.value().size(), 2U);
  EXPECT_EQ(lines.value()[0].line, 4);
  EXPECT_EQ(lines.value()[0].text, "A = 1");
  EXPECT_EQ(lines.value()[1].line, 6);
  EXPECT_EQ(lines.value()[1].text, "B = 2");
}

TEST(GsdLexer, BackslashJoinsLinesAndKeepsTheFirstLineNumber) {
  auto lines = split_logical_lines("x\r\nC = 0x01, \\ ; note\r\n   0x02,\\\r\n0x03\r\n", "f");
  ASSERT_TRUE(lines);
  ASSERT_EQ(lines.value().size(), 2U);
  EXPECT_EQ(lines.value()[1].line, 2);
  EXPECT_EQ(lines.value()[1].text, "C = 0x01,     0x02, 0x03");
}

TEST(GsdLexer, SemicolonInsideAStringIsText) {
  auto lines = split_logical_lines("Info_Text = \"a;b\" ; c", "f");
  ASSERT_TRUE(lines);
  EXPECT_EQ(lines.value()[0].text, "Info_Text = \"a;b\"");
}

TEST(GsdStatement, KeywordEqualsNumber) {
  const auto st = one("Ident_Number = 0xB756");
  EXPECT_EQ(st.keyword, "Ident_Number");
  EXPECT_TRUE(st.has_equals);
  ASSERT_EQ(st.fields.size(), 1U);
  EXPECT_EQ(st.fields[0][0].number, 0xB756);
  EXPECT_EQ(st.line, 7);
}

TEST(GsdStatement, KeywordsStartingWithDigitsAreNames) {
  EXPECT_EQ(one("9.6_supp = 1").keyword, "9.6_supp");
  EXPECT_EQ(one("MaxTsdr_1.5M = 25").keyword, "MaxTsdr_1.5M");
  EXPECT_EQ(one("12M_supp = 1").keyword, "12M_supp");
}

TEST(GsdStatement, ModuleLineHasNameFieldAndCfgField) {
  const auto st = one("Module = \"F-DI\" 0xC4,0x84, 0x84,0x05");
  ASSERT_EQ(st.fields.size(), 2U);
  EXPECT_EQ(st.fields[0][0].kind, Value::Kind::kString);
  EXPECT_EQ(st.fields[0][0].text, "F-DI");
  ASSERT_EQ(st.fields[1].size(), 4U);
  EXPECT_EQ(st.fields[1][3].number, 5);
}

TEST(GsdStatement, TypeLineWithArgsDefaultAndRange) {
  const auto st = one("BitArea(2-3) 1 0-3");
  EXPECT_TRUE(st.has_args);
  ASSERT_EQ(st.args.size(), 1U);
  EXPECT_EQ(st.args[0].kind, Value::Kind::kRange);
  EXPECT_EQ(st.args[0].number, 2);
  EXPECT_EQ(st.args[0].high, 3);
  EXPECT_FALSE(st.has_equals);
  ASSERT_EQ(st.fields.size(), 2U);
  EXPECT_EQ(st.fields[0][0].number, 1);
  EXPECT_TRUE(st.fields[1][0].is_range());
}

TEST(GsdStatement, NegativeNumbersAndNegativeRanges) {
  const auto st = one("Signed16 -5 -100--1");
  ASSERT_EQ(st.fields.size(), 2U);
  EXPECT_EQ(st.fields[0][0].number, -5);
  EXPECT_EQ(st.fields[1][0].number, -100);
  EXPECT_EQ(st.fields[1][0].high, -1);
}

TEST(GsdStatement, ListOfAllowedValues) {
  const auto st = one("Unsigned8 6 0,6,10");
  ASSERT_EQ(st.fields.size(), 2U);
  ASSERT_EQ(st.fields[1].size(), 3U);
  EXPECT_EQ(st.fields[1][2].number, 10);
}

TEST(GsdStatement, BareNumberIsAReferenceLine) {
  const auto st = one("6610");
  EXPECT_TRUE(st.keyword.empty());
  EXPECT_EQ(st.fields[0][0].number, 6610);
}

TEST(GsdStatement, ArgumentsMayFollowABlank) {
  const auto st = one("Value (0x0401) = \"FLASH\"");
  EXPECT_EQ(st.keyword, "Value");
  EXPECT_EQ(st.args[0].number, 0x0401);
  EXPECT_EQ(st.fields[0][0].text, "FLASH");
}

TEST(GsdStatement, NamesAsValues) {
  const auto st = one("Slave_Family = 3@TdF@Safety");
  EXPECT_EQ(st.fields[0][0].kind, Value::Kind::kName);
  EXPECT_EQ(st.fields[0][0].text, "3@TdF@Safety");
}

TEST(GsdStatement, KeywordComparisonIgnoresCase) {
  EXPECT_TRUE(one("ident_NUMBER = 1").is("Ident_Number"));
  EXPECT_FALSE(one("Ident_Numbers = 1").is("Ident_Number"));
}

TEST(GsdParser, BlocksCollectTheirBodies) {
  auto f = parse_syntax(
      "#Profibus_DP\nFail_Safe = 1\nPrmText = 3\nText(0) = \"x\"\nEndPrmText\n"
      "Module = \"m\" 0x10\n1\nEndModule\nSync_Mode_supp = 2\n",
      "f.gsd");
  ASSERT_TRUE(f) << f.error().what();
  const auto& e = f.value().entries;
  ASSERT_EQ(e.size(), 4U);
  EXPECT_FALSE(e[0].body.has_value());
  ASSERT_TRUE(e[1].body.has_value());
  EXPECT_EQ(e[1].body->size(), 1U);
  EXPECT_EQ(e[2].statement.line, 6);
  EXPECT_EQ(e[2].body->size(), 1U);
  EXPECT_EQ(e[3].statement.keyword, "Sync_Mode_supp");
}

TEST(GsdParser, EveryCorpusFileParses) {
  for (const char* name :
       {"compact_dpv0.gsd", "modular_dpv1.gsd", "profisafe_v2.gsd", "whitespace_comments.gsd",
        "revision1_modular.gsd", "revision2_compact.gsd"}) {
    auto f = parse_syntax(gsd::testing::corpus(name), name);
    EXPECT_TRUE(f) << name << ": " << (f ? "" : f.error().what());
  }
}

TEST(GsdParser, WhitespaceCorpusKeepsLineNumbersAndJoinsContinuations) {
  auto f = parse_syntax(gsd::testing::corpus("whitespace_comments.gsd"), "w.gsd");
  ASSERT_TRUE(f) << f.error().what();
  const auto& e = f.value().entries;
  ASSERT_EQ(e.size(), 6U);
  EXPECT_EQ(e[0].statement.line, 5);  // Ident_Number after the header on line 4
  EXPECT_EQ(e[1].statement.fields[0][0].text, "semi;colon \\ inside");
  EXPECT_EQ(e[4].statement.line, 9);  // MaxTsdr_500 continued over lines 9..11
  EXPECT_EQ(e[4].statement.fields[0][0].number, 100);
  ASSERT_TRUE(e[5].body.has_value());  // Module … endmodule (lower case)
  EXPECT_EQ(e[5].statement.fields[1].size(), 2U);
}

}  // namespace
}  // namespace rs4sim::gsd::syntax
