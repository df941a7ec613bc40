#pragma once
// GSD slaves as our class 1 master sees them (`rs4sim master --gsd-slave`, docs/gsd.md "Our
// master with GSD slaves"): each configured from its GSD (master_entry: Set_Prm with Lock_Req,
// WD_On, the GSD's Ident_Number and default User_Prm_Data, [IEC 61158-6-3 Set_Prm]; Chk_Cfg =
// the chosen modules' Cfg bytes in slot order, [IEC 61158-6-3 Chk_Cfg/Get_Cfg]) and the output
// image the master sends it, set per module. The console report is the run's
// (app/runtime/master_gsd.h), the harness API rpc/gsd_master_service.h.
//
// Our master as F-host (docs/profisafe.md "Our master as F-host for GSD F-devices"): each
// PROFIsafe F-module of a slave gets its F-parameter block written into the Set_Prm (the GSD's
// defaults, F_Dest_Add = the station's address switch when given, F_Par_CRC = CRC1 over them,
// [IEC 61784-3-3 F-Parameters, CRC1]) and a profisafe::FHost in V1 or V2 as its F_Par_Version
// says. Once per master cycle (on_master_cycle) each F-host takes the module's input bytes as
// the device's safety PDU and puts its next PDU into the module's output bytes: consecutive
// numbers, CRC2, the F_WD_Time watchdog, passivation with fail-safe values on a fault, ACK_REQ
// once the communication is healthy again and reintegration on the operator's ACK_REI
// ([PROFIsafe V1.30 F-Device behaviour] [IEC 61784-3-3 safety PDU]).

#include "dp/master/master.h"
#include "gsd/station/gsd_station.h"
#include "profisafe/f_host.h"

#include <cstdint>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace rs4sim::gsd {

// The device-related part of a Slave_Diag: what follows its 6 standard bytes
// [IEC 61158-6-3 Slave_Diag] (none: empty).
std::span<const std::uint8_t> ext_diagnosis(const dp::fdl::DataUnit& slave_diag);

// One F-module of a GSD slave with our F-host.
struct GsdMasterFModule {
  GsdMasterFModule(std::size_t module, const profisafe::FHostConfig& config,
                   std::size_t input_offset, std::size_t output_offset);

  std::size_t slot = 0;                 // the module's slot index (0-based)
  std::size_t input_offset = 0;         // of the device's PDU in the slave's input image
  std::size_t output_offset = 0;        // of the host's PDU in the slave's output image
  std::size_t pdu_size = 0;             // F-data + status/control [+ number] + CRC2
  profisafe::FParameters parameters;    // as written into the Set_Prm (par_crc = CRC1)
  profisafe::FHost host;
  std::vector<std::uint8_t> f_outputs;  // the program's F-output data (zeros at first)
  std::vector<std::uint8_t> sent;       // F-data of the last PDU sent (zeros while fail-safe)
  std::string last_fault;  // the last fault that passivated it after start-up; empty: none yet

  [[nodiscard]] std::size_t f_data_size() const noexcept { return f_outputs.size(); }
  // "V1" or "V2".
  [[nodiscard]] const char* mode() const noexcept;
};

// One GSD slave as the master side sees it.
struct GsdMasterSlave {
  GsdStationSpec spec;
  std::vector<std::uint8_t> outputs;  // the whole output image as set (zeros at first)
  std::vector<GsdMasterFModule> f_modules;  // slot order
  [[nodiscard]] const GsdMasterFModule* f_module(std::size_t slot) const;
  // "0, 2" (the F-modules' slots) or "none".
  [[nodiscard]] std::string f_slot_list() const;
};

// Why an F-module call was refused (std::error_code values of GsdMasterSlaves' F calls).
enum class FModuleError {
  kNoSlave = 1,   // no GSD slave at that address
  kNotFModule,    // the slot holds no F-module with our F-host
  kWrongLength,   // F-output data not the module's F-data length
  kNothingWaits,  // ACK_REI while no ACK_REQ stands
};
const std::error_category& f_module_category() noexcept;
std::error_code make_error_code(FModuleError e) noexcept;

class GsdMasterSlaves {
 public:
  // Writes each F-module's F-parameter block into the spec's User_Prm_Data (F_Dest_Add =
  // spec.f_dest_add when set, F_Par_CRC = CRC1). An F-module whose F-data our F-host cannot
  // serve (not 1..12 bytes, the same both ways) stays plain I/O, as on the station
  // (gsd::GsdApplication::f_modules).
  explicit GsdMasterSlaves(std::vector<GsdStationSpec> specs);

  [[nodiscard]] bool empty() const { return slaves_.empty(); }
  [[nodiscard]] const std::vector<GsdMasterSlave>& slaves() const { return slaves_; }
  [[nodiscard]] const GsdMasterSlave* find(std::uint8_t address) const;
  // "5, 6" (or "none").
  [[nodiscard]] std::string address_list() const;
  // Every GSD slave in data exchange with its F-hosts in RUN.
  [[nodiscard]] bool healthy(const dp::master::Master& master) const;

  // The outputs of the module in `slot` from the next Data_Exchange on. Errors:
  // std::errc::no_such_device_or_address (not a GSD slave), std::errc::result_out_of_range
  // (slot), std::errc::invalid_argument (not the module's output length),
  // std::errc::operation_not_permitted (an F-module: its bytes are the F-host's PDU).
  std::error_code set_outputs(dp::master::Master& master, std::uint8_t address, std::size_t slot,
                              std::span<const std::uint8_t> bytes);

  // ---- the F-hosts -------------------------------------------------------------------------
  // One PROFIsafe step per master cycle for every F-module: the answer in, the next request
  // out; `auto_ack` acknowledges every ACK_REQ at once. Returns whether an F-state changed.
  bool on_master_cycle(dp::master::Master& master, dp::TimePoint now, bool auto_ack);
  // The program's F-output data (exactly the module's F-data length), in the next new PDU.
  std::error_code set_f_outputs(std::uint8_t address, std::size_t slot,
                                std::span<const std::uint8_t> data);
  // The operator acknowledgement ACK_REI of a standing ACK_REQ; kNothingWaits otherwise.
  std::error_code acknowledge(std::uint8_t address, std::size_t slot);
  // Every F-module of every slave (for a report that walks them).
  [[nodiscard]] std::size_t f_module_count() const noexcept { return f_module_count_; }

 private:
  GsdMasterSlave* find_mutable(std::uint8_t address);
  std::error_code f_module(std::uint8_t address, std::size_t slot, GsdMasterFModule*& out);
  static bool safety_step(GsdMasterFModule& f, std::span<const std::uint8_t> inputs, bool dx,
                          dp::TimePoint now);

  std::vector<GsdMasterSlave> slaves_;
  std::size_t f_module_count_ = 0;
};

}  // namespace rs4sim::gsd

template <>
struct std::is_error_code_enum<rs4sim::gsd::FModuleError> : std::true_type {};
