// libFuzzer target: json::normalise_body (json/request_body.h), the input as a JSON request body
// for a message with an enum, bytes, a repeated message and a map. Invariants: no crash or hang;
// a refusal names a field and leaves the text as it was; an accepted text that was valid JSON
// stays valid JSON; hex_bytes of anything gives pairs (half the digits) or nothing.
#include "json/request_body.h"
#include "json/syntax.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/descriptor.pb.h>
#include <google/protobuf/text_format.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

const google::protobuf::Descriptor& body_type() {
  static google::protobuf::DescriptorPool pool;
  static const google::protobuf::Descriptor* type = [] {
    google::protobuf::FileDescriptorProto file;
    if (!google::protobuf::TextFormat::ParseFromString(R"(
      name: "f.proto" package: "f" syntax: "proto3"
      enum_type { name: "Kind" value { name: "KIND_UNSPECIFIED" number: 0 }
                  value { name: "KIND_PROTECTIVE" number: 1 } }
      message_type { name: "Entry" field { name: "data" number: 1 type: TYPE_BYTES label: LABEL_REPEATED }
                     field { name: "kind" number: 2 type: TYPE_ENUM type_name: ".f.Kind" label: LABEL_OPTIONAL } }
      message_type { name: "Body"
        field { name: "kind" number: 1 type: TYPE_ENUM type_name: ".f.Kind" label: LABEL_OPTIONAL }
        field { name: "data" number: 2 type: TYPE_BYTES label: LABEL_OPTIONAL }
        field { name: "entries" number: 3 type: TYPE_MESSAGE type_name: ".f.Entry" label: LABEL_REPEATED }
        field { name: "count" number: 4 type: TYPE_UINT64 label: LABEL_OPTIONAL } }
    )", &file)) {
      std::abort();
    }
    return pool.BuildFile(file)->FindMessageTypeByName("Body");
  }();
  return *type;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::json;
  const std::string original(reinterpret_cast<const char*>(data), size);
  std::string text = original;
  const auto refused = normalise_body(text, body_type());
  // A refusal leaves the text as it was (its field may be "": a body's key can be empty).
  if (refused && text != original) std::abort();
  if (!refused && !first_syntax_error(original) && first_syntax_error(text)) std::abort();
  const auto bytes = hex_bytes(original);
  if (bytes && (bytes->empty() || bytes->size() * 2 > original.size())) std::abort();
  return 0;
}
