#pragma once
// A PROFIsafe F-module of a GSD ([PROFIBUS GSD spec F-parameter keywords] [IEC 61784-3-3
// F-Parameters, safety PDU]): where its F-parameter block lies in the module's F-part of the
// User_Prm_Data, each named F-parameter with its default and range, the F_Par_CRC the file gives
// against CRC1 over the defaults, the descriptive CRCs, and the safety I/O the F-parameters
// select (F-data, status/control byte, V1 consecutive number, CRC2 length by version).
//
// An F-module is a module with an F-part (F_Ext_Module_Prm_Data_Len, F_Ext_User_Prm_Data_*) or
// with an F_ParamDescCRC / F_IO_StructureDescCRC. check_f_modules() refuses, with the file and
// line, an F-module without an F-parameter description, an F-parameter whose default lies
// outside the profile's range, and F-parameters or Cfg bytes that make no PROFIsafe connection.

#include "gsd/config.h"
#include "gsd/model.h"
#include "profisafe/f_parameters.h"
#include "profisafe/pdu.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rs4sim::gsd {

// One F_Ext_User_Prm_Data_Ref of the module's F-part.
struct FParamField {
  std::size_t offset = 0;            // in the module's F-part
  const ExtParam* param = nullptr;   // Device::params (lives as long as the Device)
};

// The safety PDU of the module each way: F-data + status/control byte + [V1: consecutive
// number] + CRC2 ([IEC 61784-3-3 safety PDU]).
struct SafetyIoLayout {
  profisafe::ProtocolVersion version = profisafe::ProtocolVersion::kV1;
  std::size_t crc2_bytes = 2;      // V1 2; V2 3 or 4 (F_CRC_Length)
  std::size_t number_bytes = 1;    // V1 1 (sent); V2 0 (the virtual number is not sent)
  std::size_t f_input_bytes = 0;   // F-data device → host (module input_len − overhead)
  std::size_t f_output_bytes = 0;  // F-data host → device (module output_len − overhead)
  [[nodiscard]] std::size_t overhead() const noexcept { return 1 + number_bytes + crc2_bytes; }
};

// "PROFIsafe V1, CRC2 2 bytes + consecutive number; F-inputs 4 bytes, F-outputs 4 bytes, …"
[[nodiscard]] std::string to_text(const SafetyIoLayout& io);

struct FModuleInfo {
  FParameterDefaults defaults;        // the 10 default bytes, file F_Par_CRC, CRC1
  profisafe::FParameters parameters;  // the defaults read as F-parameters
  std::vector<FParamField> fields;    // file order
  SafetyIoLayout io;
};

// "is an F-module" as the header says.
[[nodiscard]] bool is_f_module(const Module& module) noexcept;

// The protocol the F-parameters select and the F-data sizes left in the module's Cfg bytes.
// Errors: kFParameterLayout (F_Par_Version not 0 or 1, a CRC length the version does not use,
// Cfg bytes shorter than the PDU overhead or F-data longer than the version carries).
Result<SafetyIoLayout> safety_io_layout(const Module& module, const profisafe::FParameters& p);

// Errors: those of f_parameter_defaults and safety_io_layout.
Result<FModuleInfo> describe_f_module(const Device& device, const Module& module);

// Every F-module of the device, as the header says. Errors carry the file and the line of the
// module (or of the ExtUserPrmData): kMissingKeyword, kOutOfRange, kFParameterLayout.
Result<void> check_f_modules(const Device& device);

}  // namespace rs4sim::gsd
