#include "json/value_kind.h"

#include <google/protobuf/struct.pb.h>

namespace rs4sim::json {

std::string kind_of(const google::protobuf::Value& v) {
  using google::protobuf::Value;
  switch (v.kind_case()) {
    case Value::kStringValue: return "a string";
    case Value::kNumberValue: return "a number";
    case Value::kBoolValue: return "a boolean";
    case Value::kNullValue: return "null";
    case Value::kListValue: return "an array";
    case Value::kStructValue: return "an object";
    case Value::KIND_NOT_SET: break;
  }
  return "nothing";
}

}  // namespace rs4sim::json
