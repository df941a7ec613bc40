// json::kind_of for every kind of google.protobuf.Value, built by hand and parsed by protobuf.
#include "json/value_kind.h"

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>

#include <gtest/gtest.h>

#include <string>

namespace rs4sim::json {
namespace {

using google::protobuf::Value;

std::string kind_of_text(const std::string& text) {
  Value v;
  const auto status = google::protobuf::util::JsonStringToMessage(text, &v, {});
  EXPECT_TRUE(status.ok()) << text << ": " << status.message();
  return kind_of(v);
}

TEST(JsonValueKind, NamesEachKindBuiltByHand) {
  Value v;
  EXPECT_EQ(kind_of(v), "nothing");
  v.set_string_value("x");
  EXPECT_EQ(kind_of(v), "a string");
  v.set_number_value(1.5);
  EXPECT_EQ(kind_of(v), "a number");
  v.set_bool_value(false);
  EXPECT_EQ(kind_of(v), "a boolean");
  v.set_null_value(google::protobuf::NULL_VALUE);
  EXPECT_EQ(kind_of(v), "null");
  v.mutable_list_value();
  EXPECT_EQ(kind_of(v), "an array");
  v.mutable_struct_value();
  EXPECT_EQ(kind_of(v), "an object");
}

TEST(JsonValueKind, NamesEachKindParsed) {
  EXPECT_EQ(kind_of_text(R"("")"), "a string");
  EXPECT_EQ(kind_of_text("-0.5"), "a number");
  EXPECT_EQ(kind_of_text("true"), "a boolean");
  EXPECT_EQ(kind_of_text("null"), "null");
  EXPECT_EQ(kind_of_text("[]"), "an array");
  EXPECT_EQ(kind_of_text(R"({"a": 1})"), "an object");
}

}  // namespace
}  // namespace rs4sim::json
