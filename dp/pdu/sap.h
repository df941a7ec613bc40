#pragma once
// Service access points of DP and DPV1, spec/profibus-dp.md §2.1, §3.3, §3.7.
// No extension bytes at all = default SAP = Data_Exchange (§1.4).

#include <cstdint>

namespace rs4sim::dp::pdu::sap {

// Slave DSAPs (§2.1).
inline constexpr std::uint8_t kMsacC2Max = 48;         // 0…48 dynamic MSAC_C2 connections
inline constexpr std::uint8_t kMsacC2Rm = 49;          // MSAC_C2 resource manager (§3.7)
inline constexpr std::uint8_t kAlarm = 50;             // MSAC_C1 Alarm_Ack (Extra_Alarm_SAP)
inline constexpr std::uint8_t kMsacC1 = 51;            // MSAC_C1 Read/Write/Alarm_Ack (§3.3)
inline constexpr std::uint8_t kExtUserPrm = 53;        // Ext_User_Prm (DPV1)
inline constexpr std::uint8_t kSetSlaveAdd = 55;       // Set_Slave_Add (§2.7)
inline constexpr std::uint8_t kRdInp = 56;             // Rd_Inp
inline constexpr std::uint8_t kRdOutp = 57;            // Rd_Outp
inline constexpr std::uint8_t kGlobalControl = 58;     // Global_Control (§2.6)
inline constexpr std::uint8_t kGetCfg = 59;            // Get_Cfg
inline constexpr std::uint8_t kSlaveDiag = 60;         // Slave_Diag (§2.5)
inline constexpr std::uint8_t kSetPrm = 61;            // Set_Prm (§2.3)
inline constexpr std::uint8_t kChkCfg = 62;            // Chk_Cfg (§2.4)

// Master SSAPs (§2.1).
inline constexpr std::uint8_t kMasterMs0 = 62;         // slave handler: all DP services but DX
inline constexpr std::uint8_t kMasterMsac1 = 51;       // MSAC_C1
inline constexpr std::uint8_t kMasterMs2 = 50;         // "DPM2 to slave" (C2, UNCERTAIN §7.9)
inline constexpr std::uint8_t kMasterMm = 54;          // master-master

// Station addresses (§1.4).
inline constexpr std::uint8_t kMaxSlaveAddress = 125;
inline constexpr std::uint8_t kDefaultSlaveAddress = 126;
inline constexpr std::uint8_t kNoMasterAddress = 255;  // Diag.Master_Add when unparameterized

}  // namespace rs4sim::dp::pdu::sap
