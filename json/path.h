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

// `text` as a JSON string literal [RFC 8259 §7]: quotes around, '"' and '\' escaped, newline
// and tab as \n and \t, the other control characters as \u00xx; every other byte (UTF-8
// included) as it is.
std::string string_literal(std::string_view text);

}  // namespace rs4sim::json
