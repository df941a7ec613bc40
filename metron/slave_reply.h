#pragma once
// The Receiver's reply frame. Its figures (15 and 18) are lost; the only surviving fact is
// that a node-mode reply carries the responding curtain's node number [METRON manual "With
// node"]. DECISION: the reply mirrors the request,
//   Frame start | [Node] | Length | Reply code | Data | Checksum
// with Length = 1 + data bytes and the checksum over reply code + data. Codes: wire_table.h.

#include "metron/checksum.h"
#include "metron/wire_table.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::metron {

[[nodiscard]] std::vector<std::uint8_t> encode_reply(const WireTable& table,
                                                     std::optional<std::uint8_t> node,
                                                     std::uint8_t code,
                                                     std::span<const std::uint8_t> data,
                                                     ChecksumReading reading);

}  // namespace rs4sim::metron
