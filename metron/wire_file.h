#pragma once
// The wire table as a JSON file, for `rs4sim run --device metron --wire-table FILE`: a user
// with a trace of a real curtain replaces the project's EXTENSION values (wire_table.h)
// without recompiling ([docs/metron.md#wire-table]). Every key is optional; a key not given
// keeps the table's value:
//
//   {"frame_start": "0x02",                       a byte: 0..255 or "0x00".."0xFF"
//    "commands": [13 bytes, manual order],  "errors": [5 bytes, E1..E5],
//    "measurements": [6 bytes: first, last, count, free, central, run],
//    "all_beams": byte, "beam_bits": "lsb-first" | "msb-first",
//    "report_start", "report_end", "separator", "request_char": bytes,
//    "reply": {"fields": ["start", "node", "length", "code", "data", "checksum"],
//              "length_counts": ["code", "data"], "checksum_covers": ["code", "data"]},
//    "report": {"order": ["start", "data", "checksum", "end"], "checksum_over": "values"},
//    "replies": {"stop_measurement": ["maximum"],            #8: "code" and/or "maximum"
//                "beam_interrupted": byte, "beam_free": byte,  #9, one beam
//                "configuration": ["beams", "input_type", "node", "scan_cycle", "t_response"],
//                "curtain_status": {"synchronised": "0x01", ..., "input_high": "0x40"}}}
//
// This is a library of its own (rs4sim_metron_wire_file): it reads JSON with protobuf's
// parser, which the sans-I/O core rs4sim_metron does not link. No file I/O here: the caller
// reads the file.

#include "metron/wire_table.h"

#include <optional>
#include <string>
#include <string_view>

namespace rs4sim::metron {

struct WireFileIssue {
  // A JSON syntax error: "LINE:COLUMN" (from 1) of the first break of the grammar, "" for
  // JSON text protobuf's parser refuses anyway (a number beyond double, say).
  // Otherwise the key: "commands[3]", "reply.fields", "$" for the whole text, a key that is
  // not a plain word as a JSON string in brackets ("[\"\"]" for the empty key).
  std::string where;
  std::string reason;
  bool syntax = false;
};

// Applies `text` to `table`, then checks the result (check() in wire_table.h). On an issue
// `table` may be partly changed: callers apply to a copy.
[[nodiscard]] std::optional<WireFileIssue> apply_wire_json(std::string_view text, WireTable& table);

// The whole table as a file apply_wire_json() reads back to the same table.
[[nodiscard]] std::string wire_json(const WireTable& table);

}  // namespace rs4sim::metron
