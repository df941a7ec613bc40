#pragma once
// The GSD slaves of `rs4sim master` (docs/gsd.md "Our master with GSD slaves"):
//
//   rs4sim master --gsd-slave 5:X.gsd --module "5:DI 8" --module "5:DO 16" --slave 4 ...
//
// Each is configured from its GSD as for the memory bus (gsd_master_entry: Set_Prm with
// Lock_Req, WD_On, the GSD's Ident_Number and default User_Prm_Data, [IEC 61158-6-3 Set_Prm];
// Chk_Cfg = the chosen modules' Cfg bytes in slot order, [IEC 61158-6-3 Chk_Cfg/Get_Cfg]) and
// polled by the same master after the RS4s (Rs4MasterStationConfig::other_slaves). The harness
// sets the outputs the master sends, per module, and reads the inputs it received
// (rs4sim.v1.GsdMaster, rpc/proto/rs4sim/v1/gsd.proto); the report prints each slave's DP state
// and its input changes.

#include "app/devices/gsd_station.h"
#include "app/runtime/master_report.h"
#include "dp/master/master.h"
#include "rpc/executor.h"
#include "rs4sim/v1/gsd.grpc.pb.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <system_error>
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

// One GSD slave as the master side sees it.
struct GsdMasterSlave {
  GsdStationSpec spec;
  std::vector<std::uint8_t> outputs;  // the whole output image as set (zeros at first)
  // What the report last said.
  std::optional<dp::master::PollState> shown_state;
  std::vector<std::uint8_t> shown_inputs;
  std::vector<std::uint8_t> shown_diag;  // the last Slave_Diag after its 6 standard bytes
  std::string shown_diag_text;           // its GSD texts ("; "-separated)
};

class GsdMasterSlaves {
 public:
  explicit GsdMasterSlaves(std::vector<GsdStationSpec> specs);

  [[nodiscard]] bool empty() const { return slaves_.empty(); }
  [[nodiscard]] const std::vector<GsdMasterSlave>& slaves() const { return slaves_; }
  [[nodiscard]] const GsdMasterSlave* find(std::uint8_t address) const;
  // "5, 6" (or "none").
  [[nodiscard]] std::string address_list() const;
  // The master's entries, in configuration order (throws UsageError naming the file when the
  // GSD's Set_Prm does not encode).
  [[nodiscard]] std::vector<dp::master::SlaveEntry> entries(
      std::chrono::milliseconds watchdog) const;

  // Once, before the link starts: one "gsd" line per slave (file, ident, modules).
  void start(const MasterReport& report, dp::TimePoint now) const;
  // After a link call: a "dp" line when a slave's DP state changed, an "inputs" line when the
  // inputs of its last Data_Exchange changed, a "diagnosis" line when the GSD's Unit_Diag texts
  // for its last Slave_Diag changed (gsd::unit_diag_texts).
  void update(const dp::master::Master& master, const MasterReport& report, dp::TimePoint now);
  // A "stop" line per slave.
  void stopped(const dp::master::Master& master, const MasterReport& report, dp::TimePoint now) const;
  // Every GSD slave in data exchange.
  [[nodiscard]] bool healthy(const dp::master::Master& master) const;

  // The outputs of the module in `slot` from the next Data_Exchange on. Errors:
  // std::errc::no_such_device_or_address (not a GSD slave), std::errc::result_out_of_range
  // (slot), std::errc::invalid_argument (not the module's output length).
  std::error_code set_outputs(dp::master::Master& master, std::uint8_t address, std::size_t slot,
                              std::span<const std::uint8_t> bytes);

 private:
  GsdMasterSlave* find_mutable(std::uint8_t address);
  static void diagnosis(const dp::master::Master& master, const MasterReport& report,
                        dp::TimePoint now, GsdMasterSlave& s);
  std::vector<GsdMasterSlave> slaves_;
};

// rs4sim.v1.GsdMaster: requests checked on the gRPC thread, run on the loop through `executor`.
// `master` is called there (the master of the running MasterService).
class GsdMasterService final : public v1::GsdMaster::Service {
 public:
  GsdMasterService(rpc::Executor& executor, GsdMasterSlaves& slaves,
                   std::function<dp::master::Master&()> master)
      : executor_(executor), slaves_(slaves), master_(std::move(master)) {}
  grpc::Status ListSlaves(grpc::ServerContext*, const v1::Empty*,
                          v1::ListGsdMasterSlavesResponse* out) override;
  grpc::Status GetSlave(grpc::ServerContext*, const v1::StationRequest* in,
                        v1::GsdMasterSlave* out) override;
  grpc::Status SetOutputs(grpc::ServerContext*, const v1::SetGsdOutputsRequest* in,
                          v1::Empty*) override;

 private:
  rpc::Executor& executor_;
  GsdMasterSlaves& slaves_;
  std::function<dp::master::Master&()> master_;
};

}  // namespace rs4sim::app
