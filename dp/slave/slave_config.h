#pragma once
// Static configuration of one dp::Slave (what a GSD file declares about the device).
// Validated once by validate(); dp::Slave refuses an invalid config.

#include <cstdint>
#include <system_error>

namespace rs4sim::dp::slave {

struct Config {
  std::uint8_t address = 126;      // FDL address, 0…126 (126 = delivery address,
                                   // [IEC 61158-4-3 addresses, SAPs])
  std::uint16_t ident_number = 0;  // PNO ident; Set_Prm must match it ([IEC 61158-6-3 Set_Prm])

  // DP-V0 features (GSD Sync_Mode_supp / Freeze_Mode_supp / Set_Slave_Add_supp).
  bool sync_supported = false;
  bool freeze_supported = false;
  bool set_slave_add_supported = false;
  bool address_change_locked = false;  // as after Set_Slave_Add with No_Add_Chg
                                       // ([IEC 61158-6-3 Set_Slave_Add, Rd_Inp/Rd_Outp])
  std::uint8_t min_tsdr_default = 11;  // Tbit, until Set_Prm byte 3 changes it
                                       // ([IEC 61158-4-3 bus parameters, timing])
  std::uint16_t max_diag_length = 244;  // Slave_Diag reply 6…244 bytes ([IEC 61158-6-3 Slave_Diag])

  // DP-V1 (GSD DPV1_Slave, C1_Read_Write_supp, Fail_Safe, Extra_Alarm_SAP_supp …).
  bool dpv1 = false;
  bool fail_safe_supported = false;       // DPV1_Status_1 bit 6
                                          // ([IEC 61158-6-3 Data_Exchange, DPV1_Status])
  bool wd_base_1ms_supported = true;      // DPV1_Status_1 bit 2
  bool extra_alarm_sap = false;           // Alarm_Ack on SAP 50 instead of 51
                                          // ([IEC 61158-6-3 DPV1 alarms])
  std::uint8_t c1_max_data_length = 240;  // C1_Max_Data_Len ([IEC 61158-6-3 MSAC_C1])
  // Alarms ([IEC 61158-6-3 DPV1 alarms]): at most `alarm_capacity` outstanding (the effective limit
  // is also bounded by the master's Alarm_Mode); sequence numbers cycle 0…alarm_sequence_numbers−1
  // (the RS4 uses 8 and 8: "sequence mode for 8 alarms", seq in specifier bits 5..3).
  std::uint8_t alarm_capacity = 8;
  std::uint8_t alarm_sequence_numbers = 32;
  std::uint8_t alarm_queue_capacity = 32;  // submitted, not yet in a diagnosis

  // MSAC_C2 ([IEC 61158-6-3 MSAC_C2]): one connection at a time on dynamic SAP `c2_sap`.
  bool c2_supported = false;
  std::uint8_t c2_max_data_length = 240;   // C2_Max_Data_Len
  std::uint16_t c2_rm_send_timeout = 100;  // RM reply Send_Timeout, unit 10 ms (1 s)
  std::uint8_t c2_sap = 48;                // VPC3 counts dynamic SAPs down from 48

  [[nodiscard]] std::error_code validate() const;
};

}  // namespace rs4sim::dp::slave
