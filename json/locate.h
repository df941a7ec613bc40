// Where in JSON text a member named by a path stands, so that a message from a parser that
// names members but not places ("(stations[0].versions[1].source): invalid value ...",
// protobuf's) can give the line and column of the value.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace rs4sim::json {

// The byte offset of the value at `path` in `text`: steps "name" (an object member, matched
// by the name as written or by its lowerCamelCase form, as protobuf's JSON mapping allows:
// "stored_at" finds "storedAt") and "[i]" (an array element, from 0), joined by '.':
// "stations[0].versions[1].source". Nothing when the text has no such value or is not
// valid JSON up to it (run first_syntax_error first).
std::optional<std::size_t> offset_of_member(std::string_view text, std::string_view path);

}  // namespace rs4sim::json
