// json::normalise_body on a message declared here (a FieldKind-like enum, bytes, repeated,
// nested and map fields): short enum names, hex bytes, the refusals. The base64 answers are
// written out by hand: 11 22 33 44 55 66 77 88 is "ESIzRFVmd4g=", A5 is "pQ==", 00 01 is
// "AAE="; "1122334455667788" read as base64 is d7 5d b6 df 7e 38 e7 9e ba ef bf 3c (12 bytes,
// the bytes the issue saw sent).
#include "json/request_body.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/descriptor.pb.h>
#include <google/protobuf/text_format.h>

#include <gtest/gtest.h>

#include <string>

namespace rs4sim::json {
namespace {

namespace pb = google::protobuf;

const pb::Descriptor& request_type() {
  static pb::DescriptorPool pool;
  static const pb::Descriptor* type = [] {
    pb::FileDescriptorProto file;
    const bool parsed = pb::TextFormat::ParseFromString(R"(
      name: "t.proto" package: "t" syntax: "proto3"
      enum_type { name: "FieldKind"
        value { name: "FIELD_KIND_UNSPECIFIED" number: 0 }
        value { name: "FIELD_KIND_PROTECTIVE" number: 1 }
        value { name: "FIELD_KIND_WARNING" number: 2 } }
      message_type { name: "Inner"
        field { name: "kind" number: 1 type: TYPE_ENUM type_name: ".t.FieldKind" label: LABEL_OPTIONAL }
        field { name: "blob" number: 2 type: TYPE_BYTES label: LABEL_REPEATED } }
      message_type { name: "Request"
        field { name: "address" number: 1 type: TYPE_UINT32 label: LABEL_OPTIONAL }
        field { name: "field" number: 2 type: TYPE_ENUM type_name: ".t.FieldKind" label: LABEL_OPTIONAL }
        field { name: "data" number: 3 type: TYPE_BYTES label: LABEL_OPTIONAL }
        field { name: "inner" number: 4 type: TYPE_MESSAGE type_name: ".t.Inner" label: LABEL_REPEATED }
        field { name: "duration_ms" number: 5 type: TYPE_UINT64 label: LABEL_OPTIONAL json_name: "durationMs" } }
    )", &file);
    EXPECT_TRUE(parsed);
    return pool.BuildFile(file)->FindMessageTypeByName("Request");
  }();
  return *type;
}

std::string normalised(std::string text) {
  const auto refused = normalise_body(text, request_type());
  EXPECT_FALSE(refused) << refused->field << ": " << refused->reason;
  return text;
}

BodyRefusal refusal(std::string text) {
  const std::string before = text;
  const auto refused = normalise_body(text, request_type());
  EXPECT_EQ(text, before) << "a refusal leaves the text as it was";
  return refused.value_or(BodyRefusal{"(accepted)", text});
}

TEST(JsonRequestBody, ShortEnumNamesInAnyCaseBecomeTheLongOnes) {
  EXPECT_EQ(normalised(R"({"field": "protective"})"), R"({"field": "FIELD_KIND_PROTECTIVE"})");
  EXPECT_EQ(normalised(R"({"field":"WARNING","address":4})"),
            R"({"field":"FIELD_KIND_WARNING","address":4})");
  EXPECT_EQ(normalised(R"({"field": "field_kind_warning"})"), R"({"field": "FIELD_KIND_WARNING"})");
  // the long name and a number stay as they are; so does every number's spelling
  EXPECT_EQ(normalised(R"({"field": "FIELD_KIND_PROTECTIVE", "durationMs": 12345678901234567})"),
            R"({"field": "FIELD_KIND_PROTECTIVE", "durationMs": 12345678901234567})");
  EXPECT_EQ(normalised(R"({"inner": [{}, {"kind": "warning"}]})"),
            R"({"inner": [{}, {"kind": "FIELD_KIND_WARNING"}]})");
}

TEST(JsonRequestBody, AnUnknownEnumNameListsTheNames) {
  const auto r = refusal(R"({"inner": [{"kind": "side"}]})");
  EXPECT_EQ(r.field, "inner[0].kind");
  EXPECT_EQ(r.reason, "'side' is not a t.FieldKind: UNSPECIFIED, PROTECTIVE, WARNING (each also "
                      "as FIELD_KIND_NAME)");
}

TEST(JsonRequestBody, AnUnknownFieldListsTheFields) {
  const auto r = refusal(R"({"ms": 50})");
  EXPECT_EQ(r.field, "ms");
  EXPECT_EQ(r.reason, "unknown field 'ms' in t.Request; its fields: address, field, data, inner, "
                      "duration_ms (durationMs)");
  EXPECT_EQ(refusal(R"({"inner": [{"kinds": 1}]})").field, "inner[0].kinds");
  // both spellings protobuf accepts are known
  EXPECT_EQ(normalised(R"({"duration_ms": 1, "durationMs": 2})"), R"({"duration_ms": 1, "durationMs": 2})");
}

TEST(JsonRequestBody, HexWithSeparatorsOrTaggedBecomesBase64) {
  EXPECT_EQ(normalised(R"({"data": "11 22 33 44 55 66 77 88"})"), R"({"data": "ESIzRFVmd4g="})");
  EXPECT_EQ(normalised(R"({"data": "11:22:33:44:55:66:77:88"})"), R"({"data": "ESIzRFVmd4g="})");
  EXPECT_EQ(normalised(R"({"data": "hex:1122334455667788"})"), R"({"data": "ESIzRFVmd4g="})");
  EXPECT_EQ(normalised(R"({"data": "HEX:a5"})"), R"({"data": "pQ=="})");
  EXPECT_EQ(normalised(R"({"inner": [{"blob": ["00 01", "AAE="]}]})"),
            R"({"inner": [{"blob": ["AAE=", "AAE="]}]})");
  EXPECT_EQ(normalised(R"({"data": "ESIzRFVmd4g="})"), R"({"data": "ESIzRFVmd4g="})");
}

TEST(JsonRequestBody, BareHexDigitsAreRefusedWithBothReadings) {
  const auto r = refusal(R"({"data": "1122334455667788"})");
  EXPECT_EQ(r.field, "data");
  EXPECT_EQ(r.reason,
            "'1122334455667788' reads as hex (8 bytes) and as base64, protobuf's JSON for bytes "
            "(12 bytes d7 5d b6 df 7e 38 e7 9e …): write hex as 'hex:1122334455667788' or "
            "'11 22 33 44 55 66 77 88', base64 with its '=' padding where it has one");
  EXPECT_EQ(refusal(R"({"data": "A5"})").field, "data");
  EXPECT_EQ(refusal(R"({"data": "hex:1 22"})").reason,
            "'hex:1 22' is not hex bytes: pairs of hex digits, each optionally followed by a "
            "space or a colon");
  EXPECT_EQ(refusal(R"({"data": "11 22 "})").field, "data");
}

TEST(JsonRequestBody, HexBytesByHand) {
  EXPECT_EQ(hex_bytes("11 22:3a"), std::string("\x11\x22\x3a"));
  EXPECT_EQ(hex_bytes("ff"), std::string("\xff"));
  EXPECT_FALSE(hex_bytes(""));
  EXPECT_FALSE(hex_bytes("1"));
  EXPECT_FALSE(hex_bytes("11  22"));
  EXPECT_FALSE(hex_bytes("1g"));
}

TEST(JsonRequestBody, WhatItCannotJudgeIsLeftToProtobuf) {
  EXPECT_EQ(normalised(R"({"field": )"), R"({"field": )");
  EXPECT_EQ(normalised(R"({"address": "four"})"), R"({"address": "four"})");
  EXPECT_EQ(normalised(R"([1])"), R"([1])");
}

}  // namespace
}  // namespace rs4sim::json
