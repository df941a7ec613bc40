#pragma once
// The Receiver's reply frame. Its figures (15 and 18) are lost; the only surviving fact is
// that a node-mode reply carries the responding curtain's node number [METRON manual "With
// node"]. The layout is the wire table's (WireTable::reply, EXTENSION); by default
// (DECISION) the reply mirrors the request,
//   Frame start | [Node] | Length | Reply code | Data | Checksum
// with Length = 1 + data bytes and the checksum over reply code + data. Codes: wire_table.h.

#include "metron/checksum.h"
#include "metron/wire_table.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::metron {

// `node`: the node number a node-mode reply carries (nullopt without node mode).
[[nodiscard]] std::vector<std::uint8_t> encode_reply(const WireTable& table,
                                                     std::optional<std::uint8_t> node,
                                                     std::uint8_t code,
                                                     std::span<const std::uint8_t> data,
                                                     ChecksumReading reading);

// Where the checksum byte of a `frame_size`-byte reply encoded with `table` sits; nullopt
// when the layout has no checksum or the size cannot be such a reply.
[[nodiscard]] std::optional<std::size_t> reply_checksum_offset(const WireTable& table,
                                                               bool node_mode,
                                                               std::size_t frame_size);

}  // namespace rs4sim::metron
