// The retentive record of docs/proxy.md ([RS4 manual §6.4] "34 retentive bytes").
#include "proxy/retentive.h"

#include "storage/crc32.h"

namespace rs4sim::proxy {

namespace {
constexpr std::size_t kCrcOffset = 20;
constexpr std::uint8_t kFlagsDefined = 0x07;

void put16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v >> 8);
  p[1] = static_cast<std::uint8_t>(v);
}
void put32(std::uint8_t* p, std::uint32_t v) {
  put16(p, static_cast<std::uint16_t>(v >> 16));
  put16(p + 2, static_cast<std::uint16_t>(v));
}
std::uint16_t get16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>((p[0] << 8) | p[1]);
}
std::uint32_t get32(const std::uint8_t* p) {
  return (std::uint32_t{get16(p)} << 16) | get16(p + 2);
}
}  // namespace

std::array<std::uint8_t, kRetentiveSize> encode_retentive(const RetentiveRecord& r) {
  std::array<std::uint8_t, kRetentiveSize> out{};
  out[0] = kRetentiveVersion;
  out[1] = static_cast<std::uint8_t>(r.state);
  out[2] = r.step;
  out[3] = static_cast<std::uint8_t>((r.config_set_to_default ? 0x01 : 0) | (r.fb_busy ? 0x02 : 0) |
                                     (r.download_open ? 0x04 : 0));
  put16(&out[4], r.error_number_fb);
  put16(&out[6], r.error_code_sfc);
  put16(&out[8], r.error_number_rs4);
  out[10] = r.direction;
  out[11] = r.reason;
  put32(&out[12], r.serial_number);
  put32(&out[16], r.set_crc32);
  put32(&out[kCrcOffset], storage::crc32(std::span(out).first(kCrcOffset)));
  return out;
}

std::optional<RetentiveRecord> decode_retentive(std::span<const std::uint8_t> in) {
  if (in.size() != kRetentiveSize || in[0] != kRetentiveVersion) return std::nullopt;
  if (get32(&in[kCrcOffset]) != storage::crc32(in.first(kCrcOffset))) return std::nullopt;
  if (in[1] > 2 || (in[3] & ~kFlagsDefined) != 0) return std::nullopt;
  RetentiveRecord r;
  switch (in[1]) {
    case 1: r.state = RetentiveState::kSyncOpen; break;
    case 2: r.state = RetentiveState::kBackgroundVerify; break;
    default: r.state = RetentiveState::kIdle; break;
  }
  r.step = in[2];
  r.config_set_to_default = (in[3] & 0x01) != 0;
  r.fb_busy = (in[3] & 0x02) != 0;
  r.download_open = (in[3] & 0x04) != 0;
  r.error_number_fb = get16(&in[4]);
  r.error_code_sfc = get16(&in[6]);
  r.error_number_rs4 = get16(&in[8]);
  r.direction = in[10];
  r.reason = in[11];
  r.serial_number = get32(&in[12]);
  r.set_crc32 = get32(&in[16]);
  return r;
}

}  // namespace rs4sim::proxy
