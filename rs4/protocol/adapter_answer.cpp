#include "rs4/protocol/adapter_answer.h"

#include "codec/reader.h"
#include "codec/writer.h"
#include "rs4/protocol/adapter_command.h"

namespace rs4sim::rs4::protocol {
namespace {

// Checks code byte and exact length, the two ways an answer can be malformed in frame.
std::error_code check_frame(std::span<const std::uint8_t> answer, AdapterCommandCode code,
                            std::size_t size) noexcept {
  if (answer.empty() || answer[0] != static_cast<std::uint8_t>(code)) {
    return ProtocolError::kBadAnswerCode;
  }
  if (answer.size() != size) return ProtocolError::kBadAnswerLength;
  return {};
}

void put_ring(std::vector<std::uint8_t>& out, const ErrorRingBuffer& ring) {
  codec::Appender w(out);
  w.u8(ring.write_index);
  w.u8(ring.age_flag);
  for (const auto entry : ring.entries) w.u16_be(entry);
}

Result<ErrorRingBuffer> get_ring(std::span<const std::uint8_t> in) noexcept {
  ErrorRingBuffer ring;
  codec::Reader r(in);
  ring.write_index = r.u8();
  ring.age_flag = r.u8();
  if (ring.write_index >= ErrorRingBuffer::kEntries || ring.age_flag > 1) {
    return ProtocolError::kBadAnswerValue;
  }
  r.u16_be_array(ring.entries);
  if (!r.ok()) return ProtocolError::kBadAnswerLength;
  return ring;
}

constexpr std::size_t kRingSize = 2 + 2 * ErrorRingBuffer::kEntries;  // 42 bytes

}  // namespace

std::string_view to_token(SyncDirection d) noexcept {
  switch (d) {
    case SyncDirection::kNone: return "none";
    case SyncDirection::kVerify: return "verify";
    case SyncDirection::kUpload: return "upload";
    case SyncDirection::kDownload: return "download";
  }
  return "?";
}

std::vector<std::uint8_t> encode_version_answer(const VersionAnswer& a) {
  return {static_cast<std::uint8_t>(AdapterCommandCode::kGetVersion),
          a.profisafe_version_hi,
          a.profisafe_version_lo,
          a.dp_version_hi,
          a.dp_version_lo,
          a.dpv1sl_components_hi,
          a.dpv1sl_components_lo,
          a.main_interface,
          a.function,
          a.bugfix};
}

Result<VersionAnswer> decode_version_answer(std::span<const std::uint8_t> answer) {
  if (auto ec = check_frame(answer, AdapterCommandCode::kGetVersion, kVersionAnswerSize)) {
    return ec;
  }
  return VersionAnswer{answer[1], answer[2], answer[3], answer[4], answer[5],
                       answer[6], answer[7], answer[8], answer[9]};
}

std::vector<std::uint8_t> encode_last_error_answer(const LastErrorAnswer& a) {
  std::vector<std::uint8_t> out{static_cast<std::uint8_t>(AdapterCommandCode::kError)};
  out.reserve(kLastErrorAnswerSize);
  codec::Appender w(out);
  // DECISION [docs/decisions.md#rs4-uc1-count-byte-order]: high byte first
  for (const auto v : {a.uc2_error, a.uc2_count, a.uc1_error, a.uc1_count}) w.u16_be(v);
  return out;
}

Result<LastErrorAnswer> decode_last_error_answer(std::span<const std::uint8_t> answer) {
  if (auto ec = check_frame(answer, AdapterCommandCode::kError, kLastErrorAnswerSize)) {
    return ec;
  }
  codec::Reader r(answer.subspan(1));
  return LastErrorAnswer{r.u16_be(), r.u16_be(), r.u16_be(), r.u16_be()};
}

void ErrorRingBuffer::push(std::uint16_t error) noexcept {
  write_index = static_cast<std::uint8_t>((write_index + 1U) % kEntries);
  entries[write_index] = error;
  age_flag = 0;
}

std::vector<std::uint8_t> encode_error_memory_answer(const ErrorMemoryAnswer& a) {
  std::vector<std::uint8_t> out{static_cast<std::uint8_t>(AdapterCommandCode::kGetError)};
  out.reserve(kErrorMemoryAnswerSize);
  put_ring(out, a.uc2);
  put_ring(out, a.uc1);
  return out;
}

Result<ErrorMemoryAnswer> decode_error_memory_answer(std::span<const std::uint8_t> answer) {
  if (auto ec = check_frame(answer, AdapterCommandCode::kGetError, kErrorMemoryAnswerSize)) {
    return ec;
  }
  auto uc2 = get_ring(answer.subspan(1, kRingSize));
  if (!uc2) return uc2.error();
  auto uc1 = get_ring(answer.subspan(1 + kRingSize, kRingSize));
  if (!uc1) return uc1.error();
  return ErrorMemoryAnswer{uc2.value(), uc1.value()};
}

}  // namespace rs4sim::rs4::protocol

namespace rs4sim::rs4::protocol {

std::vector<std::uint8_t> encode_proxy_begin_answer(const ProxyBeginAnswer& answer) {
  return {static_cast<std::uint8_t>(AdapterCommandCode::kProxyBegin),
          static_cast<std::uint8_t>(answer.reason), static_cast<std::uint8_t>(answer.direction),
          static_cast<std::uint8_t>(answer.factory_default ? 1 : 0)};
}

Result<ProxyBeginAnswer> decode_proxy_begin_answer(std::span<const std::uint8_t> answer) {
  if (const auto ec = check_frame(answer, AdapterCommandCode::kProxyBegin, kProxyBeginAnswerSize)) {
    return ec;
  }
  const std::uint8_t reason = answer[1];
  const std::uint8_t direction = answer[2];
  const std::uint8_t flags = answer[3];
  // Reason and direction come together: none with none, something with something.
  if (reason > static_cast<std::uint8_t>(SyncReason::kUserParametrisation) ||
      direction > static_cast<std::uint8_t>(SyncDirection::kDownload) || flags > 1 ||
      (reason == 0) != (direction == 0)) {
    return ProtocolError::kBadAnswerValue;
  }
  return ProxyBeginAnswer{static_cast<SyncReason>(reason), static_cast<SyncDirection>(direction),
                          flags == 1};
}

std::vector<std::uint8_t> encode_proxy_end_answer(const ProxyEndAnswer& answer) {
  return {static_cast<std::uint8_t>(AdapterCommandCode::kProxyEnd),
          static_cast<std::uint8_t>(answer.accepted ? 1 : 0),
          static_cast<std::uint8_t>(answer.factory_default ? 1 : 0)};
}

Result<ProxyEndAnswer> decode_proxy_end_answer(std::span<const std::uint8_t> answer) {
  if (const auto ec = check_frame(answer, AdapterCommandCode::kProxyEnd, kProxyEndAnswerSize)) {
    return ec;
  }
  if (answer[1] > 1 || answer[2] > 1) return ProtocolError::kBadAnswerValue;
  return ProxyEndAnswer{answer[1] == 1, answer[2] == 1};
}

}  // namespace rs4sim::rs4::protocol
