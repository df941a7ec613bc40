#pragma once
// A whole bus from one file: `rs4sim run --bus FILE.json` (docs/gsd.md "Bus file").
//
//   {"stations": [{"address": 4, "device": "rs4"},
//                 {"address": 5, "gsd": "SI0180fd.gse", "modules": ["Basic Type 2"]}]}
//
// Every DP station device of the registry can appear with its `rs4sim run` options as keys
// (without the dashes: "address", "gsd", "modules", "ident", "cfg", "boot-time",
// "command-time", "adapter-response-time", "serial-number", "state"); "device" defaults to
// "generic" when "gsd" or "ident" is given. File names are relative to the bus file. All
// stations run on the run's one link; with --link memory our master polls them all,
// configured from the same GSDs (gsd_master_entry) or the device's own entry.
//
// Everything is checked before anything starts: JSON syntax, unknown keys, wrong types, a
// missing device, an address twice, a GSD that does not parse or lacks a module, a missing
// file — UsageError (exit 2) naming the bus file, the JSON path and the reason, e.g.
// `bus.json: $.stations[1].address: 5 is already used by $.stations[0]`.

#include "app/devices/device_registry.h"

#include <string>
#include <vector>

namespace rs4sim::app {

struct BusStation {
  std::string path;    // "$.stations[1]"
  std::string device;  // registry name
  stream::DeviceKind kind = stream::DeviceKind::kGeneric;  // the entry's kind (what code asks)
  DeviceOptions options;  // validated by the device's entry
};

struct BusFile {
  std::string file;
  std::vector<BusStation> stations;
};

// Reads and checks `file` (see above); `link_baud` is the run's PROFIBUS rate (the GSDs must
// support it).
BusFile read_bus_file(const std::string& file, const std::string& link_baud);
// Parses and checks bus-file text (for tests: `file` names it, `dir` resolves relative paths).
BusFile parse_bus_file(const std::string& text, const std::string& file, const std::string& dir,
                       const std::string& link_baud);

// A device entry "bus" that runs every station of `bus` on one link.
DeviceEntry bus_device_entry(BusFile bus);

}  // namespace rs4sim::app
