#include "gridscan/payload.h"

#include "codec/writer.h"

namespace rs4sim::gridscan {
namespace {

constexpr std::uint8_t kInterruptedBit = 0x01;      // bit 8 = byte 1 bit 0
constexpr std::uint8_t kInternalFailureBit = 0x02;  // bit 9 = byte 1 bit 1
constexpr unsigned kMaintenanceShift = 6;           // bits 14..15 = byte 1 bits 6..7

void put_state_bytes(codec::Appender<Payload>& w, const StateReport& s) {
  w.u8(s.door_position);
  std::uint8_t b1 = 0;
  if (s.interrupted) b1 |= kInterruptedBit;
  if (s.internal_failure) b1 |= kInternalFailureBit;
  b1 = static_cast<std::uint8_t>(b1 | ((s.maintenance & 0x03U) << kMaintenanceShift));
  w.u8(b1);
}

}  // namespace

Payload encode_reduced_state(const StateReport& s) {
  Payload p;
  codec::Appender w(p);
  put_state_bytes(w, s);
  return p;
}

Payload encode_full_state(const StateReport& s, unsigned element_count) {
  Payload p;
  codec::Appender w(p);
  put_state_bytes(w, s);
  const unsigned n = element_count > kMaxElements ? kMaxElements : element_count;
  const std::uint64_t mask = n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1U;
  const std::uint64_t bits = s.elements & mask;
  for (unsigned byte = 0; byte < (n + 7) / 8; ++byte) {
    w.u8(static_cast<std::uint8_t>((bits >> (8U * byte)) & 0xFFU));
  }
  return p;
}

Result<StateReport> decode_state(std::span<const std::uint8_t> payload) {
  if (payload.size() < 2) return FrameError::kPayloadLength;
  if (payload.size() > kMaxPayload) return FrameError::kPayloadLength;
  StateReport s;
  s.door_position = payload[0];
  s.interrupted = (payload[1] & kInterruptedBit) != 0;
  s.internal_failure = (payload[1] & kInternalFailureBit) != 0;
  s.maintenance = static_cast<std::uint8_t>(payload[1] >> kMaintenanceShift);
  for (std::size_t i = 2; i < payload.size(); ++i) {
    s.elements |= std::uint64_t{payload[i]} << (8U * (i - 2));
  }
  return s;
}

Result<Payload> encode_version(std::string_view sw, std::string_view hw) {
  if (sw.size() != 5 || hw.size() != 5) return FrameError::kBadField;
  Payload p;
  for (const char c : sw) p.push_back(static_cast<std::uint8_t>(c));
  for (const char c : hw) p.push_back(static_cast<std::uint8_t>(c));
  return p;
}

Result<Payload> encode_product_information(std::string_view part_number, unsigned element_count) {
  if (part_number.size() != 6) return FrameError::kBadField;
  if (element_count < kMinElements || element_count > kMaxElements) return FrameError::kBadField;
  Payload p;
  for (const char c : part_number) p.push_back(static_cast<std::uint8_t>(c));
  p.insert(p.end(), 3, std::uint8_t{0});  // bits 48..71 reserved
  p.push_back(static_cast<std::uint8_t>(element_count));
  return p;
}

Payload encode_u8(std::uint8_t v) { return Payload{v}; }

Payload encode_u16_le(std::uint16_t v) {
  Payload p;
  codec::Appender(p).u16_le(v);
  return p;
}

std::string_view to_token(CommMode m) noexcept {
  switch (m) {
    case CommMode::kPolling: return "polling";
    case CommMode::kFullStreaming: return "full-streaming";
    case CommMode::kReducedStreaming: return "reduced-streaming";
    case CommMode::kStandBy: return "stand-by";
  }
  return "?";
}

std::string_view to_token(Configuration c) noexcept {
  return c == Configuration::kStatic ? "static" : "blanking";
}

}  // namespace rs4sim::gridscan
