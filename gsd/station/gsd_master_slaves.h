#pragma once
// GSD slaves as our class 1 master sees them (`rs4sim master --gsd-slave`, docs/gsd.md "Our
// master with GSD slaves"): each configured from its GSD (master_entry: Set_Prm with Lock_Req,
// WD_On, the GSD's Ident_Number and default User_Prm_Data, [IEC 61158-6-3 Set_Prm]; Chk_Cfg =
// the chosen modules' Cfg bytes in slot order, [IEC 61158-6-3 Chk_Cfg/Get_Cfg]) and the output
// image the master sends it, set per module. The console report is the run's
// (app/runtime/master_gsd.h), the harness API rpc/gsd_master_service.h.

#include "dp/master/master.h"
#include "gsd/station/gsd_station.h"

#include <cstdint>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace rs4sim::gsd {

// The device-related part of a Slave_Diag: what follows its 6 standard bytes
// [IEC 61158-6-3 Slave_Diag] (none: empty).
std::span<const std::uint8_t> ext_diagnosis(const dp::fdl::DataUnit& slave_diag);

// One GSD slave as the master side sees it.
struct GsdMasterSlave {
  GsdStationSpec spec;
  std::vector<std::uint8_t> outputs;  // the whole output image as set (zeros at first)
};

class GsdMasterSlaves {
 public:
  explicit GsdMasterSlaves(std::vector<GsdStationSpec> specs);

  [[nodiscard]] bool empty() const { return slaves_.empty(); }
  [[nodiscard]] const std::vector<GsdMasterSlave>& slaves() const { return slaves_; }
  [[nodiscard]] const GsdMasterSlave* find(std::uint8_t address) const;
  // "5, 6" (or "none").
  [[nodiscard]] std::string address_list() const;
  // Every GSD slave in data exchange.
  [[nodiscard]] bool healthy(const dp::master::Master& master) const;

  // The outputs of the module in `slot` from the next Data_Exchange on. Errors:
  // std::errc::no_such_device_or_address (not a GSD slave), std::errc::result_out_of_range
  // (slot), std::errc::invalid_argument (not the module's output length).
  std::error_code set_outputs(dp::master::Master& master, std::uint8_t address, std::size_t slot,
                              std::span<const std::uint8_t> bytes);

 private:
  std::vector<GsdMasterSlave> slaves_;
};

}  // namespace rs4sim::gsd
