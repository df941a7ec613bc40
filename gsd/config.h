#pragma once
// Configuration of one slave from its GSD ([PROFIBUS GSD spec User_Prm_Data, modules]
// [IEC 61158-6-3 Set_Prm, DPV1_Status]): GSD + chosen modules + named parameter overrides → the
// exact Set_Prm user data and Chk_Cfg bytes a class 1 master sends. The F-parameter block of a
// PROFIsafe module gets its F_Par_CRC (CRC1, [IEC 61784-3-3 CRC1]) computed by profisafe/.
//
// gsd/ knows nothing of dp/: the app layer copies a SlaveSetup into the master's
// per-slave configuration (station address, watchdog and Station_Status are the
// master's business, not the GSD's).

#include "gsd/error.h"
#include "gsd/model.h"
#include "profisafe/f_parameters.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rs4sim::gsd {

struct ParamOverride {
  std::string name;  // ExtUserPrmData name, case-insensitive, e.g. "F_WD_Time"
  std::int64_t value = 0;
};

struct ConfigRequest {
  // The user's modules by name in slot order, after the presets (place_modules).
  std::vector<std::string> modules;
  // Applied to every placement of the named parameter (global and all modules).
  std::vector<ParamOverride> overrides;
};

inline constexpr std::size_t kGlobal = static_cast<std::size_t>(-1);

// One parameter as placed in user_prm_data (for listings and for tests).
struct PrmField {
  std::size_t offset = 0;  // in user_prm_data
  std::string name;
  ParamType type = ParamType::kUnsigned8;
  int bit_low = 0;
  int bit_high = 0;
  std::int64_t value = 0;
  std::size_t module = kGlobal;  // index into SlaveSetup::modules, or kGlobal
  bool f_parameter = false;      // placed by F_Ext_User_Prm_Data_Ref
  int param = 0;                 // ExtUserPrmData number (Device::params)
};

// One slot of the station as placed (place_modules).
struct PlacedModule {
  std::size_t index = 0;      // into Device::modules
  int slot = 0;               // slot number: Modul_Offset + position
  bool preset = false;        // placed because of `Preset = 1`, not named by the user
  bool slot_default = false;  // the default module of a SlotDefinition slot
};

// The station's slot list as the engineering tools build it ([PROFIBUS GSD spec modules,
// SlotDefinition]), the one placement every user of a GSD shares (`rs4sim run --gsd`, the bus
// file, `rs4sim gsd --prm`, our master):
//   1. the `Preset = 1` modules, in file order (FixPresetModules = 1: they cannot be left out;
//      STEP 7 and pyprofibus place them so whatever FixPresetModules says);
//   2. the user's modules, `user_modules` by name (blanks around them and case aside), in slot
//      order; each slot a SlotDefinition defines takes only the modules it allows;
//   3. the default modules of the defined slots the user left empty.
// With no user module and nothing from 1. and 3., a station whose GSD has one module takes it.
// Errors: kUnknownModule (the name is no module, or a preset one: the presets are placed
// already; the message lists the modules a user may choose), kModuleCount (a compact station
// with other than one module, a modular one with none or more than Max_Module), kOutOfRange (a
// module a SlotDefinition slot does not allow).
Result<std::vector<PlacedModule>> place_modules(const Device& device,
                                                const std::vector<std::string>& user_modules);

struct FParameterBlock {
  std::size_t module = 0;             // index into SlaveSetup::modules
  std::size_t offset = 0;             // of F_Prm_Flag1 in user_prm_data (10 bytes follow)
  profisafe::FParameters parameters;  // par_crc = the CRC1 written into the block
};

// What a class 1 master sends to set up one slave (Set_Prm user data, Chk_Cfg), as the
// GSD computes it, with the layout behind the bytes.
struct SlaveSetup {
  std::uint16_t ident_number = 0;             // Set_Prm bytes 4..5
  bool dpv1 = false;                          // DPV1_Slave = 1
  std::array<std::uint8_t, 3> dpv1_status{};  // = user_prm_data[0..2] when dpv1
  // Set_Prm DU from byte 7 on: global part (DPV1_Status_1..3 first on a DPV1 slave),
  // then per module in slot order its Ext_Module part and its F-part.
  std::vector<std::uint8_t> user_prm_data;
  std::vector<std::uint8_t> cfg;     // Chk_Cfg DU: the modules' Cfg bytes in slot order
  std::size_t input_len = 0;         // Data_Exchange input bytes (slave → master)
  std::size_t output_len = 0;        // Data_Exchange output bytes (master → slave)
  std::vector<std::string> modules;  // names, slot order (the whole slot list)
  std::vector<PlacedModule> slots;   // the same slots: module index, slot number, preset
  std::vector<PrmField> fields;
  std::vector<FParameterBlock> f_parameters;
};

// Errors: kUnknownModule, kModuleCount (compact station needs exactly one module;
// modular: at most Max_Module), kUnknownParameter (lists the known names), kOutOfRange
// ("F_WD_Time = 5 is out of range 10..1000"), kNotChangeable (Changeable = 0, or
// F_Par_CRC which is always computed), kPrmTooLong, kFParameterLayout.
Result<SlaveSetup> configure(const Device& device, const ConfigRequest& request);

// The slave's side of the same layout ([IEC 61158-6-3 Set_Prm]: a slave that does not accept its
// parameters sets Prm_Fault in its diagnosis): `user_prm_data` (the Set_Prm DU from byte 7 on,
// DPV1_Status_1..3 included) is checked as the device the GSD describes would check it: the
// length must be the configured one, and every ExtUserPrmData placed in it must hold a value
// the GSD allows (its range or list). The F-parameter blocks are left to the F-device (their
// own diagnosis, [IEC 61784-3-3 F-Parameters]); constant bytes are not checked.
// Errors (message names the byte and the parameter): kPrmTooLong (other length),
// kOutOfRange ("byte 4: Input filter (ms) = 3 is not allowed (1, 2, 5, 10)").
Result<void> check_user_prm(const Device& device, const SlaveSetup& setup,
                            std::span<const std::uint8_t> user_prm_data);

// The F-parameter block of a PROFIsafe module as its GSD writes it by default (for `rs4sim gsd
// check`): the 10 bytes of F_Prm_Flag1 … F_Par_CRC with every F_Ext_User_Prm_Data_Ref at its
// default, the F_Par_CRC the file gives, and CRC1 over the 8 bytes before it ([IEC 61784-3-3
// CRC1]). Errors: kFParameterLayout (no 2-byte F_Par_CRC reference at offset 8 or later, or the
// bytes do not read as F-parameters).
struct FParameterDefaults {
  std::vector<std::uint8_t> block;  // 10 bytes
  std::size_t offset = 0;           // of block[0] in the module's F-part
  std::uint16_t file_crc = 0;       // F_Par_CRC's default in the file
  std::uint16_t crc1 = 0;           // CRC1 over block[0..7]
};
Result<FParameterDefaults> f_parameter_defaults(const Device& device, const Module& module);

// F_ParamDescCRC as the rs4sim project defines it (docs/gsd.md; the PI algorithm for
// text GSDs is not public): CRC-16 poly 0x4EAB, preset 0 (the CRC1 polynomial) over
// the module's F constant bytes and, per F_Ext_User_Prm_Data_Ref in file order, the
// offset, the parameter name + NUL, type, bits, default, min, max and Changeable.
std::uint16_t f_param_desc_crc(const Device& device, const Module& module);

}  // namespace rs4sim::gsd
