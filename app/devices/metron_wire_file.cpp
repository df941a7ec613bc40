#include "app/devices/metron_wire_file.h"

#include "app/runtime/usage_error.h"
#include "metron/wire_file.h"

#include <fstream>
#include <sstream>

namespace rs4sim::app {

metron::WireTable read_metron_wire_table(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw UsageError("--wire-table " + file + ": cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  metron::WireTable table;
  if (const auto issue = metron::apply_wire_json(text.str(), table)) {
    if (issue->syntax && !issue->where.empty())
      throw UsageError("--wire-table " + file + ":" + issue->where + ": " + issue->reason);
    if (issue->syntax) throw UsageError("--wire-table " + file + ": " + issue->reason);
    throw UsageError("--wire-table " + file + ": " + issue->where + ": " + issue->reason);
  }
  return table;
}

}  // namespace rs4sim::app
