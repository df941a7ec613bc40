// A request body of the JSON/HTTP surface read the way people write it, before protobuf's
// JSON parser sees it (docs/http.md "Names and bytes", docs/decisions.md#http-json-bytes):
//  - an enum by its short name, in any case: "protective" for FIELD_KIND_PROTECTIVE,
//    "CORRUPT_CRC2" for SAFETY_FAULT_CORRUPT_CRC2 (the Python harness's names);
//  - bytes as hex: "hex:11 22 33" or "11 22 33" / "11:22:33"; a bare run of hex digits
//    ("1122334455667788") reads as base64 too and is refused, saying both readings;
//  - a member the message does not have is refused naming the message's fields.
// What it cannot judge (not JSON, a wrong type) it leaves to protobuf's parser.
#pragma once

#include <optional>
#include <string>

namespace google::protobuf {
class Descriptor;
}

namespace rs4sim::json {

struct BodyRefusal {
  std::string field;   // the member's path: "data", "modules[1].kind"
  std::string reason;  // "unknown field 'ms' in rs4sim.v1.AdvanceRequest; its fields: ..."
};

// Rewrites the short enum names and hex bytes of `text` (a JSON body for a message of `type`)
// into protobuf's JSON mapping, in place. A refusal leaves `text` as it was.
std::optional<BodyRefusal> normalise_body(std::string& text,
                                          const google::protobuf::Descriptor& type);

// Hex bytes as written after "hex:" or with separators: pairs of hex digits, each pair
// optionally followed by one space or colon ("11 22", "11:22", "1122"). Nothing when the text
// is not that (an odd digit, another character, empty).
std::optional<std::string> hex_bytes(std::string_view text);

}  // namespace rs4sim::json
