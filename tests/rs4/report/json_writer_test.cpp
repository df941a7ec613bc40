#include "rs4/report/json_writer.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::report {
namespace {

TEST(JsonWriter, CompactNesting) {
  JsonWriter w;
  w.begin_object().field("a", 1).key("b").begin_array().value("x").value(true).null().end_array();
  w.key("c").begin_object().end_object().key("d").raw("{\"k\":2}").end_object();
  EXPECT_EQ(w.str(), R"({"a":1,"b":["x",true,null],"c":{},"d":{"k":2}})");
}

TEST(JsonWriter, PrettyPrinted) {
  JsonWriter w(2);
  w.begin_object().field("a", -3).key("b").begin_array().value(std::int64_t{1}).end_array();
  w.key("e").begin_array().end_array().end_object();
  EXPECT_EQ(w.str(), "{\n  \"a\": -3,\n  \"b\": [\n    1\n  ],\n  \"e\": []\n}");
}

TEST(JsonWriter, EscapesStrings) {
  // Quote, backslash, newline, tab and a control byte (RFC 8259, "Strings").
  EXPECT_EQ(json_quote("a\"b\\c\nd\te\x01"), R"("a\"b\\c\nd\te\u0001")");
}

}  // namespace
}  // namespace rs4sim::rs4::report
