#pragma once
// The GSD's texts for a device-related diagnosis ([PROFIBUS GSD spec Unit_Diag_Bit,
// Unit_Diag_Area]; gsd::UnitDiag in model.h): what an engineering tool shows for a slave's
// Ext_Diag_Data.

#include "gsd/model.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rs4sim::gsd {

// `ext_diag`: the Slave_Diag DU after its 6 standard bytes ([IEC 61158-6-3 Slave_Diag]). Its first
// block must be the device-related one (header bits 7..6 = 00, bits 5..0 its length with the
// header); anything else, or a block longer than the bytes, gives no texts. In bit order: the
// text of every Unit_Diag_Bit that is set and every Unit_Diag_Not_Bit that is clear within the
// block, and for each Unit_Diag_Area inside the block the text of its value ("<area a-b>: value
// v" when the GSD names none); with them, the same of the UnitDiagType whose value is the
// block's first byte after the header (the DPV1 alarm or status type).
[[nodiscard]] std::vector<std::string> unit_diag_texts(const UnitDiag& texts,
                                                       std::span<const std::uint8_t> ext_diag);

// An F-device's diagnosis (64..71, [IEC 61784-3-3 F-Parameters]) as the device reports it: the
// last byte of the status block `05 81 slot 00 nn` ([IEC 61158-6-3 DPV1 status]), i.e. bits
// 24-31 of the block. Its text: the GSD's own, `X_Value(nn)` of a (X_)Unit_Diag_Area = 24-31
// in `UnitDiagType = 129` (the form vendors' F-module GSDs use, e.g. X_Value(64) = "F add. does
// not match F_Dest_Add") or of a Unit_Diag_Area = 24-31; where the GSD has none, the standard's
// meaning (profisafe::standard_diagnosis_text); "" for any other number.
[[nodiscard]] std::string f_diagnosis_text(const UnitDiag& texts, std::uint8_t number);

// unit_diag_texts, and for a block that is an F-device's status block with a diagnosis 64..71
// the GSD names no text for, the standard's meaning after them (`f_device`: the device has an
// F-module; without one the block is read as the GSD says and nothing more).
[[nodiscard]] std::vector<std::string> device_diag_texts(const UnitDiag& texts, bool f_device,
                                                         std::span<const std::uint8_t> ext_diag);

// The GSD's Channel_Diag text of a manufacturer-specific channel error type (16..31); "" when
// the GSD names none.
[[nodiscard]] std::string channel_error_text(const UnitDiag& texts, std::uint8_t error_type);

}  // namespace rs4sim::gsd
