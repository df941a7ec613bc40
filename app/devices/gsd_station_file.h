#pragma once
// The GSD station (gsd/station/gsd_station.h) from the file and options a user names:
// `rs4sim run --device generic --gsd FILE [--module NAME]...`, the stations of a bus file
// (app/devices/bus_file.h) and `rs4sim master --gsd-slave` (app/runtime/master_gsd.h). Every
// refusal is a UsageError (exit 2) that names the file or the option.

#include "gsd/station/gsd_station.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::app {

// The runtime names the station's types as its own.
using gsd::defines_no_user_prm;
using gsd::GsdApplication;
using gsd::GsdStation;
using gsd::GsdStationSpec;
using gsd::unchecked_user_prm_fault;

// Parses `path` and configures `modules` (empty: a compact station's one module). Throws
// UsageError (exit 2) with file:line and the reason: unreadable file, not a GSD, a syntax or
// meaning error, an unknown module (the message lists the file's modules). `warnings` gets the
// lines the parser skipped ("file:line: …").
GsdStationSpec load_gsd_station(const std::string& path, const std::vector<std::string>& modules,
                                int address, std::vector<std::string>* warnings = nullptr);

// Throws UsageError when the GSD does not support `baud` ("1.5M"; the supported ones listed).
void check_gsd_baud(const GsdStationSpec& spec, const std::string& baud);
// MaxTsdr of the GSD at `baud` (Tbit), or nullopt when the file does not say.
std::optional<std::uint16_t> gsd_max_tsdr(const GsdStationSpec& spec, const std::string& baud);

// The F-modules' F_Dest_Add `value` (--f-dest-add, bus-file "f-dest-add") checked against the
// GSD's F_Dest_Add range; throws UsageError naming the GSD's file:line of that parameter.
std::uint16_t check_f_dest_add(const GsdStationSpec& spec, int value);

// gsd::master_entry; throws UsageError naming the file when the GSD's Set_Prm does not encode.
dp::master::SlaveEntry gsd_master_entry(const GsdStationSpec& spec,
                                        std::chrono::milliseconds watchdog);

}  // namespace rs4sim::app
