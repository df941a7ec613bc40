// FDL telegram encoding, [IEC 61158-4-3 frame formats, FCS, addresses, SAPs].
#include "dp/fdl/telegram.h"

#include <cstring>
#include <stdexcept>

namespace rs4sim::dp::fdl {
namespace {

constexpr std::uint8_t kExtensionBit = 0x80;
constexpr std::uint8_t kMaxSap = 63;

// Failure paths live out of line so the checks on the hot path are a few compares.
[[noreturn, gnu::cold, gnu::noinline]] void fail(const char* what) {
  throw std::invalid_argument(what);
}

// Checks the preconditions of encode(); returns the DU length incl. extension bytes.
std::size_t checked_du_length(const Telegram& t) {
  if ((t.da | t.sa) > kBroadcastAddress) [[unlikely]]
    fail("fdl::encode: address above 127");
  if (t.dsap.has_value() != t.ssap.has_value()) [[unlikely]] {
    fail("fdl::encode: DSAP without SSAP ([IEC 61158-4-3 addresses, SAPs])");
  }
  std::size_t du = t.data.size();
  if (t.dsap) {
    if (*t.dsap > kMaxSap || *t.ssap > kMaxSap) [[unlikely]]
      fail("fdl::encode: SAP above 63");
    du += 2;
  }
  if (du > kMaxDataUnit) [[unlikely]]
    fail("fdl::encode: DU longer than 246 bytes");
  if (t.type == FrameType::kSd1 && du != 0) [[unlikely]] {
    fail("fdl::encode: SD1 carries no DU");
  }
  if (t.type == FrameType::kSd3 && du != 8) [[unlikely]] {
    fail("fdl::encode: SD3 needs exactly 8 DU bytes");
  }
  return du;
}

// Copies a DU without a library call: cyclic DUs are a few bytes, where memcpy's call and
// size dispatch cost more than the copy. 8-byte words, the last one overlapping; below 8
// bytes two overlapping 4-byte moves, below 4 three single bytes.
void copy_du(std::uint8_t* dst, const std::uint8_t* src, std::size_t n) {
  if (n >= 8) {
    for (std::size_t i = 0; i + 8 < n; i += 8) std::memcpy(dst + i, src + i, 8);
    std::memcpy(dst + n - 8, src + n - 8, 8);
  } else if (n >= 4) {
    std::memcpy(dst, src, 4);
    std::memcpy(dst + n - 4, src + n - 4, 4);
  } else if (n != 0) {
    dst[0] = src[0];
    dst[n / 2] = src[n / 2];
    dst[n - 1] = src[n - 1];
  }
}

// Writes DA SA FC [DSAP SSAP] DU FCS ED at `p`.
void put_body(const Telegram& t, std::uint8_t* p) {
  const std::uint8_t ext = t.dsap ? kExtensionBit : 0;
  p[0] = static_cast<std::uint8_t>(t.da | ext);
  p[1] = static_cast<std::uint8_t>(t.sa | ext);
  p[2] = t.fc.raw;
  unsigned sum = 0U + p[0] + p[1] + p[2];
  p += 3;
  if (t.dsap) {
    p[0] = *t.dsap;
    p[1] = *t.ssap;
    sum += 0U + p[0] + p[1];
    p += 2;
  }
  const std::size_t n = t.data.size();
  copy_du(p, t.data.data(), n);
  sum += frame_check_sequence(std::span<const std::uint8_t>(t.data.data(), n));
  p[n] = static_cast<std::uint8_t>(sum);
  p[n + 1] = kEd;
}

std::size_t wire_size(FrameType type, std::size_t du) {
  switch (type) {
    case FrameType::kShortAck: return 1;
    case FrameType::kToken: return 3;
    case FrameType::kSd1: return 6;
    case FrameType::kSd3: return 14;
    case FrameType::kSd2: return du + 9;
  }
  return 0;
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

std::size_t encoded_size(const Telegram& t) { return wire_size(t.type, checked_du_length(t)); }

std::size_t encode(const Telegram& t, std::span<std::uint8_t> out) {
  const std::size_t size = wire_size(t.type, checked_du_length(t));
  if (out.size() < size) [[unlikely]]
    fail("fdl::encode: output buffer too small");
  std::uint8_t* const p = out.data();
  switch (t.type) {
    case FrameType::kSd2:
      p[0] = kSd2;
      p[1] = static_cast<std::uint8_t>(size - 6);
      p[2] = p[1];
      p[3] = kSd2;
      put_body(t, p + 4);
      break;
    case FrameType::kSd1:
    case FrameType::kSd3:
      p[0] = t.type == FrameType::kSd1 ? kSd1 : kSd3;
      put_body(t, p + 1);
      break;
    case FrameType::kShortAck: p[0] = kSc; break;
    case FrameType::kToken:
      p[0] = kSd4;
      p[1] = t.da;
      p[2] = t.sa;
      break;
  }
  return size;
}

std::size_t encode(const Telegram& t, std::vector<std::uint8_t>& out) {
  const std::size_t old = out.size();
  out.resize(old + encoded_size(t));  // checks first: `out` is unchanged when this throws
  return encode(t, std::span<std::uint8_t>(out).subspan(old));
}

}  // namespace rs4sim::dp::fdl
