// Set_Slave_Add, [IEC 61158-6-3 Set_Slave_Add, Rd_Inp/Rd_Outp].
#include "dp/pdu/set_slave_add.h"

#include "dp/pdu/sap.h"
#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {

Result<SetSlaveAdd> decode_set_slave_add(std::span<const std::uint8_t> du) {
  if (du.size() < kSetSlaveAddFixedLength) return PduError::kTooShort;
  if (du.size() > kSetSlaveAddFixedLength + kRemSlaveDataMax) return PduError::kTooLong;
  if (du[0] > sap::kMaxSlaveAddress) return PduError::kValueOutOfRange;
  SetSlaveAdd s;
  s.new_address = du[0];
  s.ident_number = codec::be16(du[1], du[2]);
  s.no_add_chg = du[3] != 0;
  s.rem_slave_data.assign(du.begin() + kSetSlaveAddFixedLength, du.end());
  return s;
}

Result<void> encode_set_slave_add(const SetSlaveAdd& ssa, fdl::DataUnit& out) {
  if (ssa.new_address > sap::kMaxSlaveAddress) return PduError::kValueOutOfRange;
  if (out.size() + kSetSlaveAddFixedLength + ssa.rem_slave_data.size() > wire::kMaxDpDu) {
    return PduError::kTooLong;
  }
  (void)wire::append(
      out, {ssa.new_address, codec::high_byte(ssa.ident_number), codec::low_byte(ssa.ident_number),
            static_cast<std::uint8_t>(ssa.no_add_chg ? 0xFF : 0x00)});
  return wire::append(out, ssa.rem_slave_data);
}

}  // namespace rs4sim::dp::pdu
