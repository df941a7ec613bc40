#pragma once
// The meaning of a GSD ([PROFIBUS GSD spec]): what a master needs to know about a
// slave. Produced by gsd::interpret() / gsd::parse() (interp.h).

#include "gsd/error.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::gsd {

// One of the ten DP baud rates with its `<name>_supp` and `MaxTsdr_<name>` keywords.
struct BaudRate {
  std::string_view name;   // as in the keywords: "9.6" … "12M"
  std::string_view label;  // as a user types and reads it (--baud): "9.6k" … "12M"
  std::uint32_t bits_per_second = 0;
  bool supported = false;
  std::optional<std::uint16_t> max_tsdr;  // Tbit; absent when the file does not say
};

// DP-V1 capabilities ([PROFIBUS GSD spec DPV1 keywords]). Timeouts as written in the file (unit 10
// ms by convention).
struct Dpv1Info {
  bool slave = false;          // DPV1_Slave
  bool c1_read_write = false;  // C1_Read_Write_supp
  bool c2_read_write = false;  // C2_Read_Write_supp
  std::uint8_t c1_max_data_len = 0;
  std::uint8_t c2_max_data_len = 0;
  std::uint16_t c1_response_timeout = 0;
  std::uint16_t c2_response_timeout = 0;
  std::uint8_t c2_max_count_channels = 0;
  bool diagnostic_alarm = false;
  bool process_alarm = false;
  bool pull_plug_alarm = false;
  bool status_alarm = false;
  bool update_alarm = false;
  bool manufacturer_specific_alarm = false;
  std::uint8_t alarm_sequence_mode_count = 0;
  bool alarm_type_mode = false;
  bool wd_base_1ms = false;
  bool check_cfg_mode = false;
  bool prm_block_structure = false;  // Prm_Block_Structure_supp
};

enum class ParamType {
  kBit,
  kBitArea,
  kUnsigned8,
  kUnsigned16,
  kUnsigned32,
  kSigned8,
  kSigned16,
  kSigned32
};

std::string_view to_string(ParamType type);
// `s` without leading and trailing blanks and tabs (module names as a user types them).
std::string_view trim_blanks(std::string_view s);
std::size_t byte_size(ParamType type);  // bytes written at the reference offset

// ExtUserPrmData = n "name" … EndExtUserPrmData ([PROFIBUS GSD spec general keywords]).
struct ExtParam {
  int number = 0;
  std::string name;
  ParamType type = ParamType::kUnsigned8;
  int bit_low = 0;   // kBit: the bit; kBitArea: first bit
  int bit_high = 0;  // kBitArea: last bit (kBit: same as bit_low)
  std::int64_t default_value = 0;
  std::int64_t min = 0;  // allowed range when `allowed` is empty
  std::int64_t max = 0;
  std::vector<std::int64_t> allowed;  // list form `a,b,c`
  std::optional<int> prm_text_ref;
  bool changeable = true;
  bool visible = true;
  int line = 0;

  bool accepts(std::int64_t value) const;
  std::string range_text() const;  // "10..1000" or "0, 6, 10"
};

struct PrmText {
  int number = 0;
  std::map<std::int64_t, std::string> texts;  // Text(value) = "…"
};

struct PrmRef {
  std::size_t offset = 0;  // byte offset inside the template
  int param = 0;           // ExtUserPrmData number
  int line = 0;
};

// A user-parameter template: global (Max_User_Prm_Data_Len), a module's
// (Ext_Module_Prm_Data_Len) or a module's F-part (F_Ext_Module_Prm_Data_Len).
struct PrmTemplate {
  std::size_t length = 0;
  std::vector<std::uint8_t> defaults;  // zero-filled, Ext_User_Prm_Data_Const merged in
  std::vector<PrmRef> refs;            // in file order
};

struct Module {
  std::string name;
  std::vector<std::uint8_t> cfg;  // Chk_Cfg identifiers ([IEC 61158-6-3 Chk_Cfg/Get_Cfg])
  std::size_t input_len = 0;      // bytes, from the Cfg identifiers
  std::size_t output_len = 0;
  std::optional<std::uint32_t> reference;  // the bare number line after Module
  std::string info_text;
  PrmTemplate prm;
  std::optional<PrmTemplate> f_prm;  // F_Ext_Module_Prm_Data_Len / F_Ext_User_Prm_Data_*
  std::optional<std::uint16_t> f_param_desc_crc;
  std::optional<std::uint16_t> f_io_structure_desc_crc;
  // `Preset = 1` ([PROFIBUS GSD spec modules]): the engineering tool places the module in the
  // first slots, in file order, ahead of the user's modules (gsd::place_modules).
  bool preset = false;
  int line = 0;
};

// `Slot(n) = "name" default allowed` of a SlotDefinition block ([PROFIBUS GSD spec
// SlotDefinition]): the module a slot holds unless the user chooses another of `allowed`
// (module reference numbers, the bare number line of a Module block).
struct SlotDef {
  int number = 0;
  std::string name;
  std::uint32_t default_ref = 0;
  std::vector<std::uint32_t> allowed;  // includes the default
  int line = 0;
};

// The texts of the device-related diagnosis ([PROFIBUS GSD spec Unit_Diag_Bit, Unit_Diag_Area]):
// `Unit_Diag_Bit(n) = "text"` (bit n set), `Unit_Diag_Not_Bit(n) = "text"` (bit n clear), and
// `Unit_Diag_Area = a-b` … `Value(v) = "text"` … `Unit_Diag_Area_End` (bits a..b read as an
// unsigned number, bit a its least significant). Bit n is bit n % 8 of byte n / 8 after the
// device-related block's header byte (docs/decisions.md `gsd-unit-diag-bits`).
struct UnitDiagArea {
  std::uint16_t first = 0, last = 0;
  std::map<std::uint32_t, std::string> values;
  int line = 0;
};
struct UnitDiagTexts {
  std::map<std::uint16_t, std::string> bits;
  std::map<std::uint16_t, std::string> not_bits;
  std::vector<UnitDiagArea> areas;
  [[nodiscard]] bool empty() const { return bits.empty() && not_bits.empty() && areas.empty(); }
};
// Besides the texts of every device-related block: `UnitDiagType = t` … `EndUnitDiagType`
// ([PROFIBUS GSD spec UnitDiagType]), texts (X_Unit_Diag_Bit, X_Unit_Diag_Not_Bit,
// X_Unit_Diag_Area … X_Value, and the plain keywords) for a block whose first byte after the
// header, a DPV1 alarm or status type, is t, bits counted as above; and `Channel_Diag(n) =
// "text"`, the name of the manufacturer-specific channel error type n (16..31) [PROFIBUS GSD
// spec Channel_Diag, IEC 61158-6-3 Slave_Diag]. docs/decisions.md `gsd-unit-diag-types`.
struct UnitDiag : UnitDiagTexts {
  std::map<std::uint8_t, UnitDiagTexts> types;
  std::map<std::uint8_t, std::string> channel_errors;
  [[nodiscard]] bool empty() const {
    return UnitDiagTexts::empty() && types.empty() && channel_errors.empty();
  }
};

struct Device {
  std::string file;
  int gsd_revision = 0;
  std::string vendor_name;
  std::string model_name;
  std::string revision;
  std::string order_number;
  std::string info_text;
  std::uint16_t ident_number = 0;
  std::vector<BaudRate> baud_rates;  // the ten DP rates, slowest first
  bool modular_station = false;
  std::uint8_t max_module = 1;
  std::uint8_t max_input_len = 0;
  std::uint8_t max_output_len = 0;
  std::uint16_t max_data_len = 0;
  std::uint8_t max_diag_data_len = 6;
  std::uint16_t min_slave_interval = 1;  // Min_Slave_Intervall, unit 100 µs
  bool fail_safe = false;
  bool freeze_mode = false;
  bool sync_mode = false;
  bool auto_baud = false;
  bool set_slave_add = false;
  Dpv1Info dpv1;
  std::optional<std::uint8_t> max_user_prm_data_len;
  PrmTemplate user_prm;  // legacy User_Prm_Data or Ext_User_Prm_Data_*
  std::map<int, ExtParam> params;
  std::map<int, PrmText> prm_texts;
  std::vector<Module> modules;
  bool fix_preset_modules = false;  // FixPresetModules: the presets cannot be left out
  std::uint8_t modul_offset = 0;    // Modul_Offset: the slot number of the first module
  std::vector<SlotDef> slots;       // SlotDefinition, in slot number order
  UnitDiag unit_diag;
  // Slave_Family = main[@sub[@sub…]] ([PROFIBUS GSD spec Slave_Family]): 0 general, 1 drives,
  // 2 switching devices, 3 I/O, … 9 gateways …; the sub-families as written ("AS-I").
  std::optional<std::uint8_t> slave_family;
  std::vector<std::string> sub_families;
  // Lines skipped and values taken other than written (syntax::File::warnings and the
  // interpreter's), in line order.
  std::vector<Warning> warnings;
  bool latin1 = false;  // strings were ISO 8859-1, converted to UTF-8

  // By name, case-insensitive, leading and trailing blanks ignored on both sides (vendors pad
  // names: `"2 PD   (2 words)         "`); an exact match wins over a padded one.
  const Module* find_module(std::string_view name) const;
  const Module* find_module_by_reference(std::uint32_t reference) const;
  const BaudRate* find_baud(std::uint32_t bits_per_second) const;
};

}  // namespace rs4sim::gsd
