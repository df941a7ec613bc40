#include "app/devices/metron_wire_file.h"

#include "app/runtime/usage_error.h"
#include "app/runtime/whole_file.h"
#include "metron/wire_file.h"

namespace rs4sim::app {

metron::WireTable read_metron_wire_table(const std::string& file) {
  const auto text = read_whole_file(file);
  if (!text) throw UsageError("--wire-table " + file + ": cannot read the file: " + text.error);
  metron::WireTable table;
  if (const auto issue = metron::apply_wire_json(text.bytes, table)) {
    if (issue->syntax && !issue->where.empty())
      throw UsageError("--wire-table " + file + ":" + issue->where + ": " + issue->reason);
    if (issue->syntax) throw UsageError("--wire-table " + file + ": " + issue->reason);
    throw UsageError("--wire-table " + file + ": " + issue->where + ": " + issue->reason);
  }
  return table;
}

}  // namespace rs4sim::app
