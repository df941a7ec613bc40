// `rs4sim metron-wire-table`: the METRON's wire table (the project's EXTENSION byte values and
// layouts, metron/wire_table.h) as the JSON file `rs4sim run --device metron --wire-table`
// reads: the defaults to edit, or (--wire-table FILE) a file checked and completed with them.
//
//   rs4sim metron-wire-table > table.json
//   rs4sim metron-wire-table --wire-table table.json     (exit 2 with the key if it is wrong)
#include "app/cli/command.h"
#include "app/devices/metron_wire_file.h"
#include "metron/wire_file.h"

#include <iostream>
#include <memory>

namespace rs4sim::app {
namespace {

const CommandRegistration kMetronWireTable(
    "metron-wire-table",
    "print the METRON's wire table (byte values and layouts, the project's EXTENSION) as "
    "JSON for --wire-table",
    [](CLI::App& cmd) {
      auto file = std::make_shared<std::string>();
      cmd.add_option("--wire-table", *file,
                     "start from this file (checked; keys it lacks keep the defaults)");
      return [file]() {
        const auto table = file->empty() ? metron::WireTable{} : read_metron_wire_table(*file);
        std::cout << metron::wire_json(table);
        return 0;
      };
    });

}  // namespace
}  // namespace rs4sim::app
