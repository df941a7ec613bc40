// Structured parameter blocks, spec/profibus-dp.md §3.2.
#include "dp/pdu/prm_blocks.h"

#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {

Result<std::optional<PrmBlock>> PrmBlockReader::next() {
  if (rest_.empty()) return std::optional<PrmBlock>{};
  const std::size_t len = rest_[0];
  if (len < kPrmBlockHead || len > rest_.size()) {
    rest_ = {};
    return PduError::kBadPrmBlock;
  }
  const auto raw = rest_.first(len);
  rest_ = rest_.subspan(len);
  return std::optional<PrmBlock>{PrmBlock{raw[1], raw[2], raw[3], raw.subspan(kPrmBlockHead), raw}};
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
