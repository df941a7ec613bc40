#pragma once
// The GSD slaves of `rs4sim master` at the edge (docs/gsd.md "Our master with GSD slaves"):
//
//   rs4sim master --gsd-slave 5:X.gsd --module "5:DI 8" --module "5:DO 16" --slave 4 ...
//
// Each is configured from its GSD as for the memory bus (gsd_master_entry: Set_Prm with
// Lock_Req, WD_On, the GSD's Ident_Number and default User_Prm_Data, [IEC 61158-6-3 Set_Prm];
// Chk_Cfg = the chosen modules' Cfg bytes in slot order, [IEC 61158-6-3 Chk_Cfg/Get_Cfg]) and
// polled by the same master after the RS4s (Rs4MasterStationConfig::other_slaves): the options
// and the report here, the slaves' model in gsd/station/gsd_master_slaves.h, the harness's
// rs4sim.v1.GsdMaster in rpc/gsd_master_service.h. The report prints each slave's DP state,
// its input changes and the state of the F-host of each of its F-modules
// (gsd::GsdMasterFModule).

#include "app/devices/gsd_station_file.h"
#include "app/runtime/master_report.h"
#include "dp/master/master.h"
#include "gsd/station/gsd_master_slaves.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::app {

// `--gsd-slave ADDR:FILE` and `--module ADDR:NAME` (repeatable, slot order per address): the
// slaves' specs (load_gsd_station each, so a GSD error names file:line and an unknown module
// lists the file's modules), checked against `baud`. Throws UsageError naming the option: a
// malformed value, an address outside 0..125 or given twice, a --module for an address that
// has no --gsd-slave. `warnings` gets the lines the parsers skipped.
std::vector<GsdStationSpec> parse_gsd_slaves(const std::vector<std::string>& slaves,
                                             const std::vector<std::string>& modules,
                                             const std::string& baud,
                                             std::vector<std::string>* warnings = nullptr);

// `--gsd-f-dest-add ADDR:N` (repeatable): the F_Dest_Add the master writes into the F-modules'
// F-parameter blocks of that GSD slave (the device's address switch, [IEC 61784-3-3
// F-Parameters]; check_f_dest_add). Throws UsageError naming the option: a malformed value, an
// address that is no GSD slave, a slave without F-module, a value outside the GSD's range.
void apply_gsd_f_dest_adds(std::vector<GsdStationSpec>& specs,
                           const std::vector<std::string>& values);

// `--f-wd-time MS` for the GSD slaves: the F_WD_Time the master writes into every F-module's
// F-parameter block (the F-host's watchdog too). Throws UsageError naming the GSD's file:line
// when MS is outside its F_WD_Time range.
void apply_gsd_f_wd_time(std::vector<GsdStationSpec>& specs, int ms);

// The stations of a bus file (app/devices/bus_file.h, the file `rs4sim run --bus` runs on the
// other end of the line) as our master's slaves: its RS4s by address (configured from the
// built-in GSD, each with its F-host) and its GSD stations from their GSDs with their modules
// and "f-dest-add". Throws UsageError (the bus file's own refusals, and a station the master
// cannot configure: an RS4 with its own "gsd", a generic slave by "ident"/"cfg").
struct MasterBusFile {
  std::vector<int> rs4s;
  std::vector<GsdStationSpec> gsd;
};
MasterBusFile read_master_bus_file(const std::string& file, const std::string& baud);

// The console report of the GSD slaves (MasterReport::custom lines, "GSD slave N: ...").
class GsdMasterReport {
 public:
  explicit GsdMasterReport(const gsd::GsdMasterSlaves& slaves)
      : slaves_(slaves), shown_(slaves.slaves().size()) {}

  // Once, before the link starts: one "gsd" line per slave (file, ident, modules).
  void start(const MasterReport& report, dp::TimePoint now) const;
  // After a link call: a "dp" line when a slave's DP state changed, an "inputs" line when the
  // inputs of its last Data_Exchange changed (an F-module's bytes as its F-input data), a
  // "diagnosis" line when the GSD's Unit_Diag texts for its last Slave_Diag changed
  // (gsd::unit_diag_texts), a "profisafe" line when the state of an F-module's F-host changed.
  void update(const dp::master::Master& master, const MasterReport& report, dp::TimePoint now);
  // A "stop" line per slave (with its F-modules' F-host states).
  void stopped(const dp::master::Master& master, const MasterReport& report,
               dp::TimePoint now) const;

 private:
  // What the report last said of a slave.
  struct Shown {
    std::optional<dp::master::PollState> state;
    std::vector<std::uint8_t> inputs;
    std::vector<std::uint8_t> diag;  // the last Slave_Diag after its 6 standard bytes
    std::string diag_text;           // its GSD texts ("; "-separated)
    std::vector<std::optional<profisafe::FHostState>> f_states;  // per F-module
  };
  static void f_modules(const MasterReport& report, dp::TimePoint now,
                        const gsd::GsdMasterSlave& s, Shown& shown);
  static void diagnosis(const dp::master::Master& master, const MasterReport& report,
                        dp::TimePoint now, const gsd::GsdMasterSlave& s, Shown& shown);
  const gsd::GsdMasterSlaves& slaves_;
  std::vector<Shown> shown_;  // one per slave, in order
  std::vector<std::uint8_t> scratch_;  // a slave's inputs with its F-modules' F-data
};

}  // namespace rs4sim::app
