#include "rs4/protocol/block.h"

#include "codec/reader.h"
#include "codec/writer.h"
#include "rs4/protocol/adapter_error.h"

#include <algorithm>

namespace rs4sim::rs4::protocol {
namespace {

constexpr std::uint8_t kReadyBit = 0x01;
constexpr std::uint8_t kPayloadBit = 0x02;
constexpr std::uint8_t kReservedBits = 0x8C;  // bits 2, 3, 7 (table 5.2-2)
constexpr unsigned kStateShift = 4;
constexpr std::uint8_t kStateMask = 0x07;

}  // namespace

std::uint8_t encode_flow_control(const FlowControl& flow) noexcept {
  auto byte = static_cast<unsigned>(static_cast<std::uint8_t>(flow.state) & kStateMask)
              << kStateShift;
  if (flow.ready) byte |= kReadyBit;
  if (flow.payload) byte |= kPayloadBit;
  return static_cast<std::uint8_t>(byte);
}

Result<FlowControl> decode_flow_control(std::uint8_t byte) noexcept {
  if ((byte & kReservedBits) != 0) return ProtocolError::kBadFlowControl;
  const auto state = static_cast<std::uint8_t>((byte >> kStateShift) & kStateMask);
  if (state < static_cast<std::uint8_t>(FlowState::kNoCommunicationPath) ||
      state > static_cast<std::uint8_t>(FlowState::kNoConnection)) {
    return ProtocolError::kBadFlowControl;
  }
  return FlowControl{(byte & kReadyBit) != 0, (byte & kPayloadBit) != 0,
                     static_cast<FlowState>(state)};
}

Result<BlockView> decode_block(std::span<const std::uint8_t> record, Direction direction) {
  const std::size_t min_block =
      direction == Direction::kWrite ? kMinWriteRecordSize : kBlockHeaderSize;
  if (record.size() < min_block) return ProtocolError::kRecordTooShort;
  if (record.size() > kMaxRecordSize) return ProtocolError::kRecordTooLong;
  codec::Reader r(record);
  BlockHeader header;
  header.flow_control = r.u8();
  header.length = r.u8();
  header.number = r.u16_be();
  if (header.length < min_block || header.length > kMaxRecordSize) {
    return ProtocolError::kBlockLengthOutOfRange;
  }
  if (header.length > record.size()) return ProtocolError::kBlockLengthExceedsRecord;
  return BlockView{header, record.subspan(kBlockHeaderSize, header.length - kBlockHeaderSize)};
}

std::error_code encode_block(std::uint8_t flow_control, std::uint16_t number,
                             std::span<const std::uint8_t> payload,
                             std::vector<std::uint8_t>& out) {
  if (payload.size() > kMaxBlockPayload) return ProtocolError::kBlockLengthOutOfRange;
  codec::Appender w(out);
  w.u8(flow_control);
  w.u8(static_cast<std::uint8_t>(kBlockHeaderSize + payload.size()));
  w.u16_be(number);
  w.bytes(payload);
  return {};
}

// --- BlockAssembler -----------------------------------------------------------------

void BlockAssembler::reset() noexcept {
  next_number_ = 0;
  complete_ = false;
  command_.clear();
}

Result<BlockAssembler::Progress> BlockAssembler::fail(std::error_code error) noexcept {
  reset();
  return error;
}

Result<BlockAssembler::Progress> BlockAssembler::push(std::span<const std::uint8_t> record) {
  if (complete_) reset();  // the previous command was handed out
  auto block = decode_block(record, direction_);
  if (!block) return fail(block.error());
  const BlockHeader& header = block.value().header;
  // Blocks count 0, 1, 2, … and the last one is 0xFFFF ([RS4 manual §5.2.1], error 0x2A0B).
  if (!header.is_last() && header.number != next_number_) {
    return fail(AdapterError::kUnexpectedBlockNumber);
  }
  const auto payload = block.value().payload;
  if (command_.size() + payload.size() > max_command_) {
    return fail(AdapterError::kTelegramTooLong);  // whole command >= 1100 bytes (0x2A06)
  }
  command_.insert(command_.end(), payload.begin(), payload.end());
  const auto received = static_cast<std::uint16_t>(next_number_ + 1U);
  if (header.is_last()) {
    complete_ = true;
    next_number_ = 0;
  } else {
    next_number_ = received;
  }
  return Progress{complete_, received};
}

// --- BlockSplitter ------------------------------------------------------------------

BlockSplitter::BlockSplitter(std::vector<std::uint8_t> answer, std::size_t max_block_size)
    : answer_(std::move(answer)),
      max_payload_(std::clamp(max_block_size, kMinWriteRecordSize, kMaxRecordSize) -
                   kBlockHeaderSize),
      done_(false) {}

std::size_t BlockSplitter::remaining_blocks() const noexcept {
  if (done_) return 0;
  const std::size_t left = answer_.size() - offset_;
  return left == 0 ? 1 : (left + max_payload_ - 1) / max_payload_;
}

std::vector<std::uint8_t> BlockSplitter::next(FlowControl flow) {
  std::vector<std::uint8_t> block;
  if (done_) return block;
  const std::size_t size = std::min(answer_.size() - offset_, max_payload_);
  const bool last = offset_ + size == answer_.size();
  flow.payload = size != 0;
  block.reserve(kBlockHeaderSize + size);
  // size <= max_payload_ <= 236, so encode_block cannot fail here.
  (void)encode_block(encode_flow_control(flow), last ? kLastBlockNumber : number_,
                     std::span(answer_).subspan(offset_, size), block);
  offset_ += size;
  ++number_;
  done_ = last;
  return block;
}

std::vector<std::vector<std::uint8_t>> split_into_blocks(std::span<const std::uint8_t> answer,
                                                         FlowControl flow,
                                                         std::size_t max_block_size) {
  BlockSplitter splitter({answer.begin(), answer.end()}, max_block_size);
  std::vector<std::vector<std::uint8_t>> blocks;
  blocks.reserve(splitter.remaining_blocks());
  while (!splitter.done()) blocks.push_back(splitter.next(flow));
  return blocks;
}

}  // namespace rs4sim::rs4::protocol
