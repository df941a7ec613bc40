// libFuzzer target: the structure scan in front of protobuf's JSON parser (json/structure.h,
// json/message.h), the input as JSON text. Invariants: no crash or hang; a refusal points at
// the '[' or '{' it refuses; a text the grammar scanner accepts (it nests at most 100 deep)
// passes the depth scan; a depth refusal lies at or after the grammar scanner's first break;
// and json::to_message() returns (linear time: the scan stops protobuf seeing deep texts).
#include "json/message.h"
#include "json/structure.h"
#include "json/syntax.h"

#include <google/protobuf/struct.pb.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::json;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const bool arrays : {true, false}) {
    const auto e = first_structure_error(text, {kMaxDepth, arrays});
    if (e && (e->offset >= size || (text[e->offset] != '[' && text[e->offset] != '{'))) {
      std::abort();
    }
  }
  const auto deep = first_structure_error(text);
  const auto broken = first_syntax_error(text);
  if (!broken && deep) std::abort();
  if (deep && broken && broken->offset > deep->offset) std::abort();
  google::protobuf::Value value;
  (void)to_message(text, value, {});
  return 0;
}
