#include "metron/slave_reply.h"

namespace rs4sim::metron {

std::vector<std::uint8_t> encode_reply(const WireTable& table, std::optional<std::uint8_t> node,
                                       std::uint8_t code, std::span<const std::uint8_t> data,
                                       ChecksumReading reading) {
  std::vector<std::uint8_t> out;
  out.reserve(data.size() + 5);
  out.push_back(table.frame_start);
  if (node) out.push_back(*node);
  out.push_back(static_cast<std::uint8_t>(1 + data.size()));
  const auto body_at = out.size();
  out.push_back(code);
  out.insert(out.end(), data.begin(), data.end());
  out.push_back(checksum(std::span<const std::uint8_t>(out).subspan(body_at), reading));
  return out;
}

}  // namespace rs4sim::metron
