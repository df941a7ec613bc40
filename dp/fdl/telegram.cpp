// FDL telegram encoding, spec/profibus-dp.md §1.2–§1.4.
#include "dp/fdl/telegram.h"

#include <array>
#include <stdexcept>

namespace rs4sim::dp::fdl {
namespace {

constexpr std::uint8_t kExtensionBit = 0x80;
constexpr std::uint8_t kMaxSap = 63;

std::size_t extension_bytes(const Telegram& t) {
  return (t.dsap ? 1U : 0U) + (t.ssap ? 1U : 0U);
}

// Checks the preconditions of encode(); returns the DU length incl. extension bytes.
std::size_t checked_du_length(const Telegram& t) {
  if (t.da > kBroadcastAddress || t.sa > kBroadcastAddress) {
    throw std::invalid_argument("fdl::encode: address above 127");
  }
  if (t.dsap.has_value() != t.ssap.has_value()) {
    throw std::invalid_argument("fdl::encode: DSAP without SSAP (§1.4)");
  }
  if ((t.dsap && *t.dsap > kMaxSap) || (t.ssap && *t.ssap > kMaxSap)) {
    throw std::invalid_argument("fdl::encode: SAP above 63");
  }
  const std::size_t du = extension_bytes(t) + t.data.size();
  if (du > kMaxDataUnit) throw std::invalid_argument("fdl::encode: DU longer than 246 bytes");
  switch (t.type) {
    case FrameType::kSd1:
      if (du != 0) throw std::invalid_argument("fdl::encode: SD1 carries no DU");
      break;
    case FrameType::kSd3:
      if (du != 8) throw std::invalid_argument("fdl::encode: SD3 needs exactly 8 DU bytes");
      break;
    case FrameType::kSd2:
    case FrameType::kToken:
    case FrameType::kShortAck:
      break;
  }
  return du;
}

}  // namespace

Telegram make_short_ack() {
  Telegram t;
  t.type = FrameType::kShortAck;
  return t;
}

Telegram make_token(std::uint8_t da, std::uint8_t sa) {
  Telegram t;
  t.type = FrameType::kToken;
  t.da = da;
  t.sa = sa;
  return t;
}

Telegram make_data_telegram(std::uint8_t da, std::uint8_t sa, FrameControl fc,
                            std::optional<std::uint8_t> dsap, std::optional<std::uint8_t> ssap,
                            std::span<const std::uint8_t> data) {
  Telegram t;
  t.da = da;
  t.sa = sa;
  t.fc = fc;
  t.dsap = dsap;
  t.ssap = ssap;
  if (data.size() > kMaxDataUnit) throw std::invalid_argument("fdl: DU longer than 246 bytes");
  t.data.assign(data.begin(), data.end());
  t.type = (data.empty() && !dsap && !ssap) ? FrameType::kSd1 : FrameType::kSd2;
  return t;
}

std::uint8_t frame_check_sequence(std::span<const std::uint8_t> da_to_du) {
  unsigned sum = 0;
  for (const std::uint8_t b : da_to_du) sum += b;
  return static_cast<std::uint8_t>(sum & 0xFFU);
}

std::size_t encoded_size(const Telegram& t) {
  const std::size_t du = checked_du_length(t);
  switch (t.type) {
    case FrameType::kShortAck: return 1;
    case FrameType::kToken: return 3;
    case FrameType::kSd1: return 6;
    case FrameType::kSd3: return 14;
    case FrameType::kSd2: return du + 9;
  }
  return 0;
}

std::size_t encode(const Telegram& t, std::span<std::uint8_t> out) {
  const std::size_t size = encoded_size(t);
  if (out.size() < size) throw std::invalid_argument("fdl::encode: output buffer too small");
  if (t.type == FrameType::kShortAck) {
    out[0] = kSc;
    return 1;
  }
  if (t.type == FrameType::kToken) {
    out[0] = kSd4;
    out[1] = t.da;
    out[2] = t.sa;
    return 3;
  }
  std::size_t pos = 0;
  if (t.type == FrameType::kSd2) {
    const auto le = static_cast<std::uint8_t>(size - 6);
    out[0] = kSd2;
    out[1] = le;
    out[2] = le;
    out[3] = kSd2;
    pos = 4;
  } else {
    out[0] = t.type == FrameType::kSd1 ? kSd1 : kSd3;
    pos = 1;
  }
  const std::size_t first = pos;
  out[pos++] = static_cast<std::uint8_t>(t.da | (t.dsap ? kExtensionBit : 0));
  out[pos++] = static_cast<std::uint8_t>(t.sa | (t.ssap ? kExtensionBit : 0));
  out[pos++] = t.fc.raw;
  if (t.dsap) out[pos++] = *t.dsap;
  if (t.ssap) out[pos++] = *t.ssap;
  for (const std::uint8_t b : t.data) out[pos++] = b;
  out[pos] = frame_check_sequence(out.subspan(first, pos - first));
  ++pos;
  out[pos++] = kEd;
  return pos;
}

std::size_t encode(const Telegram& t, std::vector<std::uint8_t>& out) {
  std::array<std::uint8_t, kMaxTelegramSize> buf{};
  const std::size_t n = encode(t, std::span<std::uint8_t>(buf));
  out.insert(out.end(), buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(n));
  return n;
}

}  // namespace rs4sim::dp::fdl
