#pragma once
// Set_Slave_Add (DSAP 55), [IEC 61158-6-3 Set_Slave_Add, Rd_Inp/Rd_Outp].
// DU: [0] New_Slave_Add (0…125) [1..2] Ident_Number (BE) [3] No_Add_Chg [4..] Rem_Slave_Data.

#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <boost/container/static_vector.hpp>

#include <cstdint>
#include <span>

namespace rs4sim::dp::pdu {

inline constexpr std::size_t kSetSlaveAddFixedLength = 4;
inline constexpr std::size_t kRemSlaveDataMax = 238;

struct SetSlaveAdd {
  std::uint8_t new_address = 0;
  std::uint16_t ident_number = 0;
  bool no_add_chg = false;  // TRUE: address may change again only after a reset
  boost::container::static_vector<std::uint8_t, kRemSlaveDataMax> rem_slave_data;
  friend bool operator==(const SetSlaveAdd&, const SetSlaveAdd&) = default;
};

// Errors: kTooShort (< 4), kTooLong (Rem_Slave_Data > 238), kValueOutOfRange (address
// > 125). No_Add_Chg: 0x00 = FALSE, any other value = TRUE (encoded as 0xFF).
Result<SetSlaveAdd> decode_set_slave_add(std::span<const std::uint8_t> du);
Result<void> encode_set_slave_add(const SetSlaveAdd& ssa, fdl::DataUnit& out);

}  // namespace rs4sim::dp::pdu
