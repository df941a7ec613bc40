// libFuzzer target: the METRON's wire-table file (metron/wire_file.h), the input as JSON text.
// Invariants: no crash or hang; a text it accepts gives a table that validate() accepts and
// that wire_json() prints back to the same table; a refused text names where (a key, "$", or
// a line:column / nothing for a syntax error) and why.
#include "metron/wire_file.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::metron;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  WireTable table;
  const auto issue = apply_wire_json(text, table);
  if (issue) {
    if (issue->reason.empty() || (!issue->syntax && issue->where.empty())) std::abort();
    return 0;
  }
  if (!validate(table).empty()) std::abort();
  WireTable again;
  if (apply_wire_json(wire_json(table), again) || !(again == table)) std::abort();
  return 0;
}
