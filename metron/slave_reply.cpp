#include "metron/slave_reply.h"

namespace rs4sim::metron {
namespace {

// Bytes of a field other than the data (the node only in node mode).
std::size_t fixed_size(ReplyField f, bool node_mode) {
  if (f == ReplyField::kData) return 0;
  return f == ReplyField::kNode && !node_mode ? 0 : 1;
}

}  // namespace

std::vector<std::uint8_t> encode_reply(const WireTable& table, std::optional<std::uint8_t> node,
                                       std::uint8_t code, std::span<const std::uint8_t> data,
                                       ChecksumReading reading) {
  const auto& layout = table.reply;
  // Length from the fields' sizes; the checksum over the covered fields' bytes (a sum: their
  // order does not matter).
  std::size_t counted = 0;
  for (const auto f : layout.fields) {
    const std::size_t size = f == ReplyField::kData ? data.size() : fixed_size(f, node.has_value());
    if (contains(layout.length_counts, f)) counted += size;
  }
  const auto length = static_cast<std::uint8_t>(counted);
  const auto append = [&](std::vector<std::uint8_t>& out, ReplyField f) {
    switch (f) {
      case ReplyField::kStart: out.push_back(table.frame_start); return;
      case ReplyField::kNode:
        if (node) out.push_back(*node);
        return;
      case ReplyField::kLength: out.push_back(length); return;
      case ReplyField::kCode: out.push_back(code); return;
      case ReplyField::kData: out.insert(out.end(), data.begin(), data.end()); return;
      case ReplyField::kChecksum: return;
    }
  };
  std::vector<std::uint8_t> out;
  out.reserve(data.size() + layout.fields.size());
  for (const auto f : layout.fields)
    if (contains(layout.checksum_covers, f)) append(out, f);
  const auto sum = checksum(out, reading);
  out.clear();
  for (const auto f : layout.fields) {
    if (f == ReplyField::kChecksum)
      out.push_back(sum);
    else
      append(out, f);
  }
  return out;
}

std::optional<std::size_t> reply_checksum_offset(const WireTable& table, bool node_mode,
                                                 std::size_t frame_size) {
  const auto& fields = table.reply.fields;
  std::size_t fixed = 0;
  for (const auto f : fields) fixed += fixed_size(f, node_mode);
  if (frame_size < fixed) return std::nullopt;
  const std::size_t data = frame_size - fixed;
  std::size_t at = 0;
  for (const auto f : fields) {
    if (f == ReplyField::kChecksum) return at;
    at += f == ReplyField::kData ? data : fixed_size(f, node_mode);
  }
  return std::nullopt;
}

}  // namespace rs4sim::metron
