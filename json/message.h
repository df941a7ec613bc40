// JSON text into a protobuf message, the one way every reader of the project does it: the
// linear structure scan (structure.h) first, so nesting beyond the limit is refused in time
// linear in the text before protobuf's parser (quadratic in the nesting) sees it; then
// protobuf's JSON parser. And a long value cut short for a message.
#pragma once

#include "json/structure.h"

#include <google/protobuf/util/json_util.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace google::protobuf {
class Message;
}

namespace rs4sim::json {

// Parses `text` into `message`. A structure refusal is INVALID_ARGUMENT with the message
// "L:C: reason" (line and column of the offending bracket); protobuf's own refusal keeps its
// code, its message cut to kMessageLimit bytes (it may quote a value of any length).
google::protobuf::util::Status to_message(std::string_view text,
                                          google::protobuf::Message& message,
                                          const google::protobuf::util::JsonParseOptions& options,
                                          StructureRules rules = {});

// How many bytes of a value or a foreign message an error message repeats.
inline constexpr std::size_t kMessageLimit = 200;

// `text` itself when it has at most `limit` bytes; else its first bytes (never a UTF-8
// sequence cut in two) and "… (N bytes)".
std::string cut(std::string_view text, std::size_t limit = kMessageLimit);

}  // namespace rs4sim::json
