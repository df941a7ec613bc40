// The wire-table file (metron/wire_file.h): partial files keep the defaults, bytes as numbers
// or "0x.." strings, layouts by name; every bad input names its key (or line:column) and why.
#include "metron/wire_file.h"

#include <gtest/gtest.h>

#include <string>

namespace rs4sim::metron {
namespace {

using RF = ReplyField;

// The issue of `json` applied to the default table, as "where: reason".
std::string issue_of(const std::string& json) {
  WireTable t;
  const auto issue = apply_wire_json(json, t);
  return issue ? issue->where + ": " + issue->reason : std::string("none");
}

TEST(MetronWireFile, DeepNestingIsRefusedBeforeProtobufParsesIt) {
  // {"commands": is offsets 0-11 (the object is depth 0), the first '[' at 12 opens depth 1,
  // the 101st '[' at 112 depth 101: column 113.
  const std::string deep = "{\"commands\":" + std::string(50'000, '[') +
                           std::string(50'000, ']') + "}";
  EXPECT_EQ(issue_of(deep), "1:113: not valid JSON: nested deeper than 100");
}

TEST(MetronWireFile, EmptyObjectKeepsTheDefaults) {
  WireTable t;
  EXPECT_FALSE(apply_wire_json("{}", t));
  EXPECT_EQ(t, WireTable{});
}

TEST(MetronWireFile, PartialFileChangesOnlyItsKeys) {
  WireTable t;
  const auto issue = apply_wire_json(R"({
    "frame_start": "0x7E",
    "commands": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, "0x0d", "0x0C"],
    "beam_bits": "msb-first",
    "separator": 59,
    "reply": {"fields": ["start", "code", "length", "data", "checksum"],
              "length_counts": ["data"]},
    "report": {"checksum_over": "characters"}
  })",
                                     t);
  ASSERT_FALSE(issue) << issue->where << ": " << issue->reason;
  WireTable want;
  want.frame_start = 0x7E;
  want.commands[11] = 0x0D;
  want.commands[12] = 0x0C;
  want.beam_bits_lsb_first = false;
  want.separator = ';';
  want.reply.fields = {RF::kStart, RF::kCode, RF::kLength, RF::kData, RF::kChecksum};
  want.reply.length_counts = field_bit(RF::kData);
  want.report.checksum_over_characters = true;
  EXPECT_EQ(t, want);  // errors, measurements, checksum_covers, report.order: defaults
}

TEST(MetronWireFile, PrintedTableReadsBackToTheSameTable) {
  WireTable changed;
  changed.errors = {0xF1, 0xF2, 0xF3, 0xF4, 0xF5};
  changed.all_beams = 0xFF;
  changed.reply.fields = {RF::kNode, RF::kCode, RF::kData, RF::kChecksum};
  changed.reply.length_counts = 0;
  changed.reply.checksum_covers = field_bit(RF::kNode) | field_bit(RF::kData);
  changed.report.order = {ReportField::kEnd, ReportField::kData, ReportField::kChecksum,
                          ReportField::kStart};
  for (const WireTable& table : {WireTable{}, changed}) {
    WireTable read;
    read.frame_start = 0x55;  // overwritten: the printed file has every key
    const auto issue = apply_wire_json(wire_json(table), read);
    ASSERT_FALSE(issue) << issue->where << ": " << issue->reason;
    EXPECT_EQ(read, table);
  }
  EXPECT_NE(wire_json(WireTable{}).find("\"commands\": [\"0x01\", \"0x02\""), std::string::npos);
}

TEST(MetronWireFile, SyntaxErrorHasLineAndColumn) {
  WireTable t;
  const auto issue = apply_wire_json("{\n  \"frame_start\": 2,\n  \"separator\": x\n}", t);
  ASSERT_TRUE(issue);
  EXPECT_TRUE(issue->syntax);
  EXPECT_EQ(issue->where, "3:16");  // the x: line 3 is `  "separator": x`, x its 16th byte
  EXPECT_EQ(issue->reason, "not valid JSON: expected a value");
  // The text ends after the 2 (offset 11, 1:12) where ',' or ']' must come.
  const auto unterminated = apply_wire_json("{\"a\": [1, 2", t);
  ASSERT_TRUE(unterminated);
  EXPECT_TRUE(unterminated->syntax);
  EXPECT_EQ(unterminated->where, "1:12");
  EXPECT_EQ(unterminated->reason, "not valid JSON: expected ',' or ']' after an array element");
}

// The same broken line three times: any excerpt of protobuf's message around the first x also
// occurs around the second, so a search for the excerpt cannot place it; the scanner does.
TEST(MetronWireFile, SyntaxErrorInRepeatedTextHasTheFirstPosition) {
  const std::string line = "  \"commands\": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, x]";
  // cols 1-2 spaces, 3-13 "commands":, 14 space, 15 [, 16-42 "1, ".."9, ", 43-54 "10, ".."12, ",
  // 55 the x
  EXPECT_EQ(issue_of("{\n" + line + ",\n" + line + ",\n" + line + "\n}"),
            "2:55: not valid JSON: expected a value");
}

// JSON by the grammar (1e999 is a number there) that protobuf's parser refuses: its message,
// without a position.
TEST(MetronWireFile, JsonThatProtobufRefusesHasNoPosition) {
  WireTable t;
  const auto issue = apply_wire_json(R"({"frame_start": 1e999})", t);
  ASSERT_TRUE(issue);
  EXPECT_TRUE(issue->syntax);
  EXPECT_EQ(issue->where, "");
  // protobuf's words (its first line; an excerpt of the text and a caret follow)
  EXPECT_EQ(issue->reason.substr(0, issue->reason.find('\n')),
            "not valid JSON: Number exceeds the range of double.");
}

TEST(MetronWireFile, BadKeysAndValuesNameTheirKey) {
  EXPECT_EQ(issue_of(R"({"frame_begin": 2})"),
            "frame_begin: unknown key (the wire table takes: frame_start, commands, errors, "
            "measurements, all_beams, beam_bits, report_start, report_end, separator, "
            "request_char, reply, report, replies)");
  EXPECT_EQ(issue_of(R"({"frame_start": 256})"),
            "frame_start: 256 is not a byte (0..255 or \"0x00\"..\"0xFF\")");
  EXPECT_EQ(issue_of(R"({"frame_start": -1})"),
            "frame_start: -1 is not a byte (0..255 or \"0x00\"..\"0xFF\")");
  EXPECT_EQ(issue_of(R"({"frame_start": 2.5})"),
            "frame_start: 2.5 is not a byte (0..255 or \"0x00\"..\"0xFF\")");
  EXPECT_EQ(issue_of(R"({"separator": "0x100"})"),
            "separator: \"0x100\" is not a byte (0..255 or \"0x00\"..\"0xFF\")");
  EXPECT_EQ(issue_of(R"({"separator": "0xG1"})"),
            "separator: \"0xG1\" is not a byte (0..255 or \"0x00\"..\"0xFF\")");
  EXPECT_EQ(issue_of(R"({"separator": true})"),
            "separator: expected a byte (0..255 or \"0x00\"..\"0xFF\"), found a boolean");
  EXPECT_EQ(issue_of(R"({"commands": [1, 2, 3]})"),
            "commands: expected 13 bytes (#1..#13 in the manual's order), found 3");
  EXPECT_EQ(issue_of(R"({"errors": [225, 226, 227, 228, 300]})"),
            "errors[4]: 300 is not a byte (0..255 or \"0x00\"..\"0xFF\")");
  EXPECT_EQ(issue_of(R"({"measurements": {"first": 1}})"),
            "measurements: expected an array, found an object");
  EXPECT_EQ(issue_of(R"({"beam_bits": "lsb"})"),
            "beam_bits: \"lsb\": expected \"lsb-first\" or \"msb-first\"");
  EXPECT_EQ(issue_of(R"({"reply": {"fields": ["start", "crc"]}})"),
            "reply.fields[1]: no reply field \"crc\" (fields: start, node, length, code, data, "
            "checksum)");
  // A key that is not a plain word is named as a JSON string: the fuzzer found that the empty
  // key named no place at all.
  EXPECT_EQ(issue_of(R"({"": 1})"),
            R"([""]: unknown key (the wire table takes: frame_start, commands, errors, )"
            "measurements, all_beams, beam_bits, report_start, report_end, separator, "
            "request_char, reply, report, replies)");
  EXPECT_EQ(issue_of(R"({"reply": {"a b": 1}})"),
            R"(reply["a b"]: unknown key (reply takes: fields, length_counts, checksum_covers))");
  EXPECT_EQ(issue_of(R"({"reply": {"order": []}})"),
            "reply.order: unknown key (reply takes: fields, length_counts, checksum_covers)");
  EXPECT_EQ(issue_of(R"({"reply": {"length_counts": ["code", "code"]}})"),
            "reply.length_counts[1]: \"code\" is listed twice");
  EXPECT_EQ(issue_of(R"({"report": {"order": ["start", "data", "end"]}})"),
            "report.order: expected 4 parts (start, data, checksum, end in some order), found 3");
  EXPECT_EQ(issue_of(R"({"report": {"checksum_over": "digits"}})"),
            "report.checksum_over: \"digits\": expected \"values\" or \"characters\"");
  EXPECT_EQ(issue_of("[1]"), "$: expected an object {\"commands\": [...], ...}");
}

TEST(MetronWireFile, ClashesAndBrokenLayoutsNameTheirKey) {
  EXPECT_EQ(issue_of(R"({"commands": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 12]})"),
            "commands: two commands share a code");
  EXPECT_EQ(issue_of(R"({"errors": [225, 226, 3, 228, 229]})"),
            "errors: error answer code 0x03 is also a command code");
  EXPECT_EQ(issue_of(R"({"errors": [225, 225, 227, 228, 229]})"),
            "errors: two error answers share a code");
  EXPECT_EQ(issue_of(R"({"measurements": [1, 1, 3, 4, 5, 6]})"),
            "measurements: two measurements share a code");
  EXPECT_EQ(issue_of(R"({"all_beams": 7})"),
            "all_beams: the all-beams selector must be 0x00 or 0xFF (beam numbers use the rest)");
  EXPECT_EQ(issue_of(R"({"report_end": 2})"), "report_end: report start and end are equal");
  EXPECT_EQ(issue_of(R"({"reply": {"fields": ["start", "code", "checksum"]}})"),
            "reply.fields: a reply needs \"data\" (what the requests ask for)");
  EXPECT_EQ(issue_of(R"({"reply": {"fields": ["data", "data"]}})"),
            "reply.fields: the reply lists \"data\" twice");
  EXPECT_EQ(issue_of(R"({"reply": {"fields": ["start", "data", "checksum"]}})"),
            "reply.fields: a reply needs \"code\" (without it E1..E5 and an empty answer look "
            "alike)");
  EXPECT_EQ(issue_of(R"({"reply": {"fields": ["code", "length", "data", "checksum"],
                         "length_counts": ["node", "data"]}})"),
            "reply.length_counts: the Length byte counts \"node\", which the reply does not "
            "carry");
  EXPECT_EQ(issue_of(R"({"separator": "0x03"})"),
            "separator: the separator 0x03 is also the report's start or end character");
  EXPECT_EQ(issue_of(R"({"separator": 2})"),
            "separator: the separator 0x02 is also the report's start or end character");
  EXPECT_EQ(issue_of(R"({"reply": {"checksum_covers": ["start", "checksum"]}})"),
            "reply.checksum_covers: the checksum cannot sum itself");
  EXPECT_EQ(issue_of(R"({"reply": {"fields": ["code", "data"], "length_counts": [],
                         "checksum_covers": ["code", "length"]}})"),
            "reply.checksum_covers: the checksum covers \"length\", which the reply does not "
            "carry");
  EXPECT_EQ(issue_of(R"({"report": {"order": ["start", "data", "data", "end"]}})"),
            "report.order: the report order must list \"start\", \"data\", \"checksum\" and "
            "\"end\" once each (Table 1: one character before and one after the data, one "
            "checksum character)");
}

// What #8, #9 (one beam), #11 and #13 return is the table's too (EXTENSION,
// docs/metron.md#replies): read, printed back, and refused with the key named.
TEST(MetronWireFile, RepliesAreReadAndPrintedBack) {
  WireTable t;
  ASSERT_FALSE(apply_wire_json(R"({"replies": {
      "stop_measurement": ["code", "maximum"],
      "beam_interrupted": "0x00", "beam_free": "0xFF",
      "configuration": ["t_response", "beams"],
      "curtain_status": {"interrupted": "0x01", "synchronised": "0x80", "input_high": 0}}})",
                               t));
  ReplyData want;
  want.stop_measurement = {StopItem::kCode, StopItem::kMaximum};
  want.beam_interrupted = 0x00;
  want.beam_free = 0xFF;
  want.configuration = {ConfigItem::kTResponse, ConfigItem::kBeams};
  want.curtain_status = {0x80, 0x02, 0x04, 0x08, 0x10, 0x01, 0x00};
  EXPECT_EQ(t.replies, want);
  WireTable back;
  ASSERT_FALSE(apply_wire_json(wire_json(t), back));
  EXPECT_EQ(back, t);
  EXPECT_NE(wire_json(WireTable{}).find(
                R"("configuration": ["beams", "input_type", "node", "scan_cycle", "t_response"])"),
            std::string::npos);
}

TEST(MetronWireFile, BadRepliesNameTheirKey) {
  EXPECT_EQ(issue_of(R"({"replies": {"configuration": ["beams", "pitch"]}})"),
            "replies.configuration[1]: no item \"pitch\" (items: beams, input_type, node, "
            "scan_cycle, t_response)");
  EXPECT_EQ(issue_of(R"({"replies": {"configuration": ["beams", "beams"]}})"),
            "replies.configuration: #11 must return at least one item, each once");
  EXPECT_EQ(issue_of(R"({"replies": {"stop_measurement": []}})"),
            "replies.stop_measurement: #8 must return \"code\" and/or \"maximum\", each once");
  EXPECT_EQ(issue_of(R"({"replies": {"beam_free": 1}})"),
            "replies.beam_free: a free beam must differ from an interrupted one");
  EXPECT_EQ(issue_of(R"({"replies": {"curtain_status": {"measuring": "0x03"}}})"),
            "replies.curtain_status: each flag takes its own single bit (or 0: not reported), "
            "not 0x03");
  EXPECT_EQ(issue_of(R"({"replies": {"curtain_status": {"measuring": "0x01"}}})"),
            "replies.curtain_status: each flag takes its own single bit (or 0: not reported), "
            "not 0x01");
  EXPECT_EQ(issue_of(R"({"replies": {"curtain_status": {"dusty": 1}}})"),
            "replies.curtain_status.dusty: unknown flag (flags: synchronised, ossd_enabled, "
            "ossd_standby, ossd_measuring, measuring, interrupted, input_high)");
  EXPECT_EQ(issue_of(R"({"replies": {"answers": 1}})"),
            "replies.answers: unknown key (replies takes: stop_measurement, beam_interrupted, "
            "beam_free, configuration, curtain_status)");
}

TEST(MetronWireFile, ValidateNamesLayoutProblemsToo) {
  WireTable t;
  t.reply.fields = {RF::kStart, RF::kCode};
  EXPECT_EQ(validate(t), "wire table: a reply needs \"data\" (what the requests ask for)");
}

}  // namespace
}  // namespace rs4sim::metron
