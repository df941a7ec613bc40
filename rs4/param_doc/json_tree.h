#pragma once
// Internal to rs4/param_doc: the JSON text parsed by protobuf's JSON parser into a
// google.protobuf.Value tree, and typed access that refuses with the JSON path and the
// reason (thrown as Refusal inside the library, returned as a DocumentIssue at its edge).

#include "rs4/param_doc/document_error.h"

#include <google/protobuf/struct.pb.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

namespace rs4sim::rs4::param_doc::json {

using Value = google::protobuf::Value;
using Object = google::protobuf::Struct;
using List = google::protobuf::ListValue;

struct Refusal {
  DocumentIssue issue;
};
[[noreturn]] void refuse(DocumentError e, std::string path, std::string reason);

// Refusal{kSyntax} with the parser's message.
Value parse(std::string_view text);

std::string key_path(const std::string& path, std::string_view key);
std::string index_path(const std::string& path, std::size_t index);

const Object& object(const Value& v, const std::string& path);
const List& list(const Value& v, const std::string& path);
const std::string& text(const Value& v, const std::string& path);
double number(const Value& v, const std::string& path);  // finite
// An integral number in min..max; `what` completes the reason ("mm (protective field
// limit, [RS4 manual §2.3])").
std::int64_t integer(const Value& v, const std::string& path, std::int64_t min, std::int64_t max,
                     std::string_view what);

// Every key of `o` must be one of `allowed`; a key naming a password is refused as such.
void check_keys(const Object& o, const std::string& path,
                std::initializer_list<std::string_view> allowed);
// The member `key` or nullptr.
const Value* find(const Object& o, std::string_view key);

}  // namespace rs4sim::rs4::param_doc::json
