#include "gridscan/frame.h"

#include "codec/reader.h"
#include "codec/writer.h"
#include "gridscan/crc32_mpeg2.h"

#include <algorithm>

namespace rs4sim::gridscan {

std::optional<CommandId> command_of(std::uint8_t id_byte) noexcept {
  switch (static_cast<std::uint8_t>(id_byte & kIdMask)) {
    case 0x10: return CommandId::kModeSetPolling;
    case 0x11: return CommandId::kModeSetFullStreaming;
    case 0x12: return CommandId::kModeSetReducedStreaming;
    case 0x13: return CommandId::kModeSetStandBy;
    case 0x14: return CommandId::kModeGetCurrent;
    case 0x20: return CommandId::kInfoGetVersion;
    case 0x21: return CommandId::kInfoGetProductInformation;
    case 0x22: return CommandId::kInfoGetCountOfElements;
    case 0x23: return CommandId::kInfoCommunicationTest;
    case 0x24: return CommandId::kInfoGetAlignmentValue;
    case 0x25: return CommandId::kInfoRequestAlignmentMode;
    case 0x30: return CommandId::kDataReducedState;
    case 0x31: return CommandId::kDataFullState;
    case 0x40: return CommandId::kSafetyTestInput;
    case 0x50: return CommandId::kConfigAllowChange;
    case 0x51: return CommandId::kConfigSetStatic;
    case 0x52: return CommandId::kConfigSetBlanking;
    case 0x53: return CommandId::kConfigGetCurrent;
    default: return std::nullopt;
  }
}

std::vector<std::uint8_t> encode(const Frame& f) {
  std::vector<std::uint8_t> out;
  out.reserve(kMinFrame + f.payload.size());
  codec::Appender w(out, kMaxFrame);
  w.bytes(kSyncBytes);
  w.u8(f.seq);
  w.u8(f.id);
  w.bytes(std::span<const std::uint8_t>(f.payload.data(), f.payload.size()));
  w.u32_le(crc32_mpeg2(std::span<const std::uint8_t>(out).subspan(4)));
  return out;
}

Result<RawFrame> inspect(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < kMinFrame) return FrameError::kTooShort;
  if (bytes.size() > kMaxFrame) return FrameError::kTooLong;
  RawFrame raw;
  codec::Reader r(bytes);
  const auto sync = r.bytes(kSyncBytes.size());
  raw.sync_ok = std::ranges::equal(sync, kSyncBytes);
  raw.frame.seq = r.u8();
  raw.frame.id = r.u8();
  const auto payload = r.bytes(bytes.size() - kMinFrame);
  raw.frame.payload.assign(payload.begin(), payload.end());
  raw.crc_received = r.u32_le();
  raw.crc_computed = crc32_mpeg2(bytes.subspan(4, bytes.size() - 4 - kCrcSize));
  return raw;
}

namespace {

// Length, sync, CRC, ID known: the checks both directions share.
Result<RawFrame> checked(std::span<const std::uint8_t> bytes) {
  auto raw = inspect(bytes);
  if (!raw) return raw;
  if (!raw.value().sync_ok) return FrameError::kBadSync;
  if (!raw.value().crc_ok()) return FrameError::kBadCrc;
  if (!command_of(raw.value().frame.id)) return FrameError::kUnknownId;
  return raw;
}

}  // namespace

Result<Frame> decode_request(std::span<const std::uint8_t> bytes) {
  auto raw = checked(bytes);
  if (!raw) return raw.error();
  const Frame& f = raw.value().frame;
  if ((f.id & kDirectionBit) != 0) return FrameError::kDirectionBit;
  if (!f.payload.empty()) return FrameError::kRequestPayload;
  return f;
}

Result<Frame> decode_response(std::span<const std::uint8_t> bytes, unsigned elements) {
  auto raw = checked(bytes);
  if (!raw) return raw.error();
  const Frame& f = raw.value().frame;
  if ((f.id & kDirectionBit) == 0) return FrameError::kDirectionBit;
  const auto expected = response_payload_size(*command_of(f.id), elements);
  if (f.payload.size() != expected) return FrameError::kPayloadLength;
  return f;
}

std::size_t response_payload_size(CommandId c, unsigned elements) noexcept {
  switch (c) {
    case CommandId::kModeGetCurrent:
    case CommandId::kInfoGetCountOfElements:
    case CommandId::kInfoCommunicationTest:
    case CommandId::kConfigAllowChange:
    case CommandId::kConfigSetStatic:
    case CommandId::kConfigSetBlanking:
    case CommandId::kConfigGetCurrent: return 1;
    case CommandId::kInfoGetVersion:
    case CommandId::kInfoGetProductInformation: return 10;
    case CommandId::kInfoGetAlignmentValue:
    case CommandId::kDataReducedState: return 2;
    case CommandId::kDataFullState: return 2 + std::min<std::size_t>((elements + 7) / 8, 8);
    default: return 0;  // mode set, alignment mode, test input: no data
  }
}

}  // namespace rs4sim::gridscan
