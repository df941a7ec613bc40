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

// The GSD's Channel_Diag text of a manufacturer-specific channel error type (16..31); "" when
// the GSD names none.
[[nodiscard]] std::string channel_error_text(const UnitDiag& texts, std::uint8_t error_type);

}  // namespace rs4sim::gsd
