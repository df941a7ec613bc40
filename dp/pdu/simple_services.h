#pragma once
// DP services whose request carries no data: Slave_Diag, Get_Cfg, Rd_Inp, Rd_Outp
// ([IEC 61158-6-3 SAP assignment, Set_Slave_Add, Rd_Inp/Rd_Outp]), and the I/O images they return.

#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <cstdint>
#include <span>

namespace rs4sim::dp::pdu {

// Max I/O image of one slave (Max_Input_Len / Max_Output_Len ≤ 244,
// [IEC 61158-6-3 Chk_Cfg/Get_Cfg]).
inline constexpr std::size_t kMaxIoLength = 244;

// Slave_Diag.req / Get_Cfg.req / Rd_Inp.req / Rd_Outp.req carry an empty DU.
// Returns PduError::kNotEmpty otherwise.
Result<void> decode_empty_request(std::span<const std::uint8_t> du);

// Rd_Inp.res / Rd_Outp.res / Data_Exchange: the DU is the I/O image itself (0…244 B).
Result<void> encode_io_image(std::span<const std::uint8_t> image, fdl::DataUnit& out);
Result<std::span<const std::uint8_t>> decode_io_image(std::span<const std::uint8_t> du);

}  // namespace rs4sim::dp::pdu
