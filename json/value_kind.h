// What a JSON value is, as a message names it: "expected an integer, found a string".
#pragma once

#include <string>

namespace google::protobuf {
class Value;
}

namespace rs4sim::json {

// "a string", "a number", "a boolean", "null", "an array", "an object", or "nothing" (a Value
// with no kind set).
std::string kind_of(const google::protobuf::Value& v);

}  // namespace rs4sim::json
