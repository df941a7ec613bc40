#pragma once
// Service access points of DP and DPV1, [IEC 61158-6-3 SAP assignment, MSAC_C1, MSAC_C2].
// No extension bytes at all = default SAP = Data_Exchange ([IEC 61158-4-3 addresses, SAPs]).

#include <cstdint>

namespace rs4sim::dp::pdu::sap {

// Slave DSAPs ([IEC 61158-6-3 SAP assignment]).
inline constexpr std::uint8_t kMsacC2Max = 48;   // 0…48 dynamic MSAC_C2 connections
inline constexpr std::uint8_t kMsacC2Rm = 49;    // MSAC_C2 resource manager
                                                 // ([IEC 61158-6-3 MSAC_C2])
inline constexpr std::uint8_t kAlarm = 50;       // MSAC_C1 Alarm_Ack (Extra_Alarm_SAP)
inline constexpr std::uint8_t kMsacC1 = 51;      // MSAC_C1 Read/Write/Alarm_Ack
                                                 // ([IEC 61158-6-3 MSAC_C1])
inline constexpr std::uint8_t kExtUserPrm = 53;  // Ext_User_Prm (DPV1)
// Set_Slave_Add ([IEC 61158-6-3 Set_Slave_Add, Rd_Inp/Rd_Outp])
inline constexpr std::uint8_t kSetSlaveAdd = 55;
inline constexpr std::uint8_t kRdInp = 56;          // Rd_Inp
inline constexpr std::uint8_t kRdOutp = 57;         // Rd_Outp
inline constexpr std::uint8_t kGlobalControl = 58;  // Global_Control
                                                    // ([IEC 61158-6-3 Global_Control])
inline constexpr std::uint8_t kGetCfg = 59;         // Get_Cfg
inline constexpr std::uint8_t kSlaveDiag = 60;      // Slave_Diag ([IEC 61158-6-3 Slave_Diag])
inline constexpr std::uint8_t kSetPrm = 61;         // Set_Prm ([IEC 61158-6-3 Set_Prm])
inline constexpr std::uint8_t kChkCfg = 62;         // Chk_Cfg ([IEC 61158-6-3 Chk_Cfg/Get_Cfg])

// Master SSAPs ([IEC 61158-6-3 SAP assignment]).
inline constexpr std::uint8_t kMasterMs0 = 62;    // slave handler: all DP services but DX
inline constexpr std::uint8_t kMasterMsac1 = 51;  // MSAC_C1
inline constexpr std::uint8_t kMasterMs2 = 50;    // "DPM2 to slave" (C2, UNCERTAIN
                                                  // [docs/decisions.md#dp-open-points])
inline constexpr std::uint8_t kMasterMm = 54;     // master-master

// Station addresses ([IEC 61158-4-3 addresses, SAPs]): a master or a slave is 0..126, 127
// is the broadcast address (fdl::kBroadcastAddress); a slave in operation is 0..125, 126 is
// the delivery address only Set_Slave_Add moves it from.
inline constexpr std::uint8_t kMaxStationAddress = 126;
inline constexpr std::uint8_t kMaxSlaveAddress = 125;
inline constexpr std::uint8_t kDefaultSlaveAddress = 126;
inline constexpr std::uint8_t kNoMasterAddress = 255;  // Diag.Master_Add when unparameterized

}  // namespace rs4sim::dp::pdu::sap
