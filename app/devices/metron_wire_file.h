#pragma once
// `--wire-table FILE` of `rs4sim run --device metron` and `rs4sim metron-wire-table`: the
// METRON's EXTENSION byte values and layouts from a JSON file (metron/wire_file.h,
// docs/metron.md#wire-table). Errors are UsageError (exit 2) naming the file and the key,
// or the file's line:column for a JSON syntax error.

#include "metron/wire_table.h"

#include <string>

namespace rs4sim::app {

// The default table with `file`'s keys applied and checked.
[[nodiscard]] metron::WireTable read_metron_wire_table(const std::string& file);

}  // namespace rs4sim::app
