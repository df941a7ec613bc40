// How a message names a member of a JSON document: "$.stations[2].gsd", or, for a key that
// is not a plain word (empty, a space, a quote, a control character), "$[\"a b\"]" with the
// key escaped as a JSON string, so the path stays one readable line and never comes out
// empty or ambiguous.
#pragma once

#include <string>
#include <string_view>

namespace rs4sim::json {

// `parent` joined with `key`: parent + "." + key for a key of letters, digits, '_' and '-';
// otherwise parent + "[" + the key as a JSON string + "]". An empty parent gives the key
// alone for a plain word ("frame_start"), or the bracket form ("[\"\"]").
std::string member_path(std::string_view parent, std::string_view key);

// `key` as a JSON string literal: quotes around, '"' and '\' escaped, control characters and
// DEL as \u00XX; other bytes (UTF-8 included) as they are.
std::string string_literal(std::string_view key);

}  // namespace rs4sim::json
