#pragma once
// Master side of an RS4/PROFIsafe ([RS4 manual §5.1, §6.2, §6.3]; [IEC 61158-6-3 class 1 master]):
// the dp::Master entry configured from the shipped GSD (gsd::configure → Set_Prm user
// data + Chk_Cfg), and a PROFIsafe F-host over the 5-byte cyclic PDUs.
//
// gsd/ and dp/ know nothing of each other; this is the place that connects them for the RS4.

#include "dp/master/master_config.h"
#include "gsd/config.h"
#include "profisafe/f_host.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rs4sim::rs4::device {

struct Rs4MasterOptions {
  std::uint8_t address = 4;                    // the RS4's station address
  std::chrono::milliseconds dp_watchdog{200};  // Set_Prm WD (base 10 ms)
  // F_WD_Time unless overridden: the GSD default 10 ms is below the [RS4 manual §6.2, §6.6] sizing
  // 2·max(10 ms, t_scan_rec) + 4·Bus_Cycle_Time ([RS4 manual §7.3.1]: > 60 ms in practice).
  std::uint16_t f_wd_time_ms = 150;
  // GSD parameter overrides, e.g. {"F_WD_Time", 150}. F_Dest_Add defaults to
  // 500 + address ([RS4 manual §4.5]) unless overridden here (to provoke diagnosis 66).
  std::vector<gsd::ParamOverride> overrides;
  // Fault injection: F_Par_CRC sent in Set_Prm instead of the computed CRC1 (the device
  // answers with PROFIsafe diagnosis 72, [RS4 manual §6.2, §6.3]). The F-host keeps the correct
  // CRC1.
  std::optional<std::uint16_t> f_par_crc_override;
  // The GSD the entry is configured from and its module (nullptr: the built-in file; `rs4sim
  // run --device rs4 --gsd FILE --link memory` configures our master from the user's file).
  // The device outlives the call only; the entry copies what it needs.
  const gsd::Device* device = nullptr;
  std::string module;
};

struct Rs4MasterEntry {
  dp::master::SlaveEntry slave;         // for dp::master::MasterConfig::slaves
  gsd::SlaveSetup gsd;                  // what the GSD produced (fields, F-block offset)
  profisafe::FParameters f_parameters;  // incl. the CRC1 written into the block
};

// Errors: the gsd::Error of configure() (unknown parameter, out of range, …).
gsd::Result<Rs4MasterEntry> rs4_master_entry(const Rs4MasterOptions& options);

// The F-host for that entry: F-parameters as in the Set_Prm block, 1 F-data byte each way.
[[nodiscard]] profisafe::FHostConfig rs4_fhost_config(const Rs4MasterEntry& entry);

// Offset of F_Par_CRC (high byte first) in the User_Prm_Data of the GSD configuration.
[[nodiscard]] std::size_t f_par_crc_offset(const Rs4MasterEntry& entry);

}  // namespace rs4sim::rs4::device
