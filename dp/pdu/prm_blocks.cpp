// Structured parameter blocks, [IEC 61158-6-3 structured Prm_Data].
#include "dp/pdu/prm_blocks.h"

#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {

Result<std::optional<PrmBlock>> PrmBlockReader::next() {
  if (in_.at_end()) return std::optional<PrmBlock>{};
  codec::Reader peek = in_;
  const std::size_t len = peek.u8();  // Structure_Length, incl. itself
  const auto raw = in_.bytes(len);
  if (len < kPrmBlockHead || !in_.ok()) {
    in_.fail();
    return PduError::kBadPrmBlock;
  }
  codec::Reader head(raw.subspan(1));
  return std::optional<PrmBlock>{PrmBlock{head.u8(), head.u8(), head.u8(), head.rest(), raw}};
}

Result<void> encode_prm_block(std::uint8_t type, std::uint8_t slot, std::uint8_t index,
                              std::span<const std::uint8_t> data, fdl::DataUnit& out) {
  const std::size_t len = kPrmBlockHead + data.size();
  if (len > 0xFF) return PduError::kValueOutOfRange;
  if (out.size() + len > wire::kMaxDpDu) return PduError::kTooLong;
  (void)wire::append(out, {static_cast<std::uint8_t>(len), type, slot, index});
  return wire::append(out, data);
}

}  // namespace rs4sim::dp::pdu
