#pragma once
// Acyclic block protocol of the RS4/PROFIsafe ([RS4 manual §5.2.1];
// [RS4 manual §5.2.1], tables 5.2-1 and 5.2-2). Every DPV1 record on slot 0, index 2/3
// starts with a 4-byte header:
//   byte 1  flow-control byte (set by the adapter in READ answers, 0 from the master)
//   byte 2  block length in bytes including the header
//   byte 3  block number high byte (blocks count from 0)
//   byte 4  block number low byte; the last block is always 0xFFFF
// DECISION ([docs/decisions.md#rs4-block-size]): WRITE blocks of 5..240 bytes are accepted, READ
// answers use blocks of at most 240 bytes, an empty READ answer is the 4-byte header alone.

#include "rs4/protocol/errors.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::rs4::protocol {

inline constexpr std::size_t kBlockHeaderSize = 4;
inline constexpr std::size_t kMaxRecordSize = 240;     // [RS4 manual §5.2] "max 240 bytes"
inline constexpr std::size_t kMinWriteRecordSize = 5;  // [RS4 manual §5.2] "min 5"
inline constexpr std::size_t kMaxBlockPayload = kMaxRecordSize - kBlockHeaderSize;
inline constexpr std::size_t kMaxCommandSize = 1099;  // [RS4 manual §5.2.1]: >= 1100 bytes → 0x2A06
inline constexpr std::uint16_t kLastBlockNumber = 0xFFFF;
// READ answers: block numbers 0..0xFFFE plus the last one, 236 payload bytes each.
inline constexpr std::size_t kMaxReadAnswerSize = std::size_t{0x10000} * kMaxBlockPayload;

// Flow-control byte bits 6..4, table 5.2-2.
enum class FlowState : std::uint8_t {
  kNoCommunicationPath = 0b001,  // adapter still starting (class 2 only)
  kPcAdapterAttached = 0b010,    // WRITEs ignored without error
  kProxyBusy = 0b011,            // the Proxy-FB runs an acyclic command
  kNormal = 0b100,               // READ/WRITE allowed subject to bits 0 and 1
  kNoConnection = 0b101,         // no class 1 master, no PC adapter (class 2 only)
};

struct FlowControl {
  bool ready = false;    // bit 0: adapter takes the first/next WRITE block
  bool payload = false;  // bit 1: this block carries payload
  FlowState state = FlowState::kNormal;
  friend bool operator==(const FlowControl&, const FlowControl&) = default;
};

std::uint8_t encode_flow_control(const FlowControl& flow) noexcept;
// kBadFlowControl: bit 2, 3 or 7 set, or state 000, 110, 111.
Result<FlowControl> decode_flow_control(std::uint8_t byte) noexcept;

struct BlockHeader {
  std::uint8_t flow_control = 0;  // raw: the master writes 0 ([RS4 manual §5.2.1])
  std::uint8_t length = kBlockHeaderSize;
  std::uint16_t number = kLastBlockNumber;
  bool is_last() const noexcept { return number == kLastBlockNumber; }
  friend bool operator==(const BlockHeader&, const BlockHeader&) = default;
};

// A block as found in a record: header + the payload bytes the header describes.
struct BlockView {
  BlockHeader header;
  std::span<const std::uint8_t> payload;
};

enum class Direction : std::uint8_t {
  kWrite,  // master → adapter: block 5..240 bytes
  kRead,   // adapter → master: block 4..240 bytes (header-only when empty)
};

// Parses one record. Bytes behind the header's length are ignored ([RS4 manual §5.2]: "only the
// bytes described by the header are evaluated"). The flow byte is not interpreted.
Result<BlockView> decode_block(std::span<const std::uint8_t> record, Direction direction);

// Appends header + payload to out; kBlockLengthOutOfRange (nothing appended) when the
// payload exceeds 236 bytes.
[[nodiscard]] std::error_code encode_block(std::uint8_t flow_control, std::uint16_t number,
                                           std::span<const std::uint8_t> payload,
                                           std::vector<std::uint8_t>& out);

// Reassembles a command from consecutive records ([RS4 manual §5.2.1]). Errors:
// AdapterError::kTelegramTooLong (0x2A06: WRITE side, whole command >= 1100 bytes;
// READ side, more than max_command bytes — answers have no limit in the manual),
// AdapterError::kUnexpectedBlockNumber (0x2A0B) or a ProtocolError from
// decode_block. After an error the partial command is dropped and the next command
// must start with block 0 (or a single block 0xFFFF).
class BlockAssembler {
 public:
  explicit BlockAssembler(Direction direction = Direction::kWrite)
      : BlockAssembler(direction,
                       direction == Direction::kWrite ? kMaxCommandSize : kMaxReadAnswerSize) {}
  BlockAssembler(Direction direction, std::size_t max_command)
      : direction_(direction), max_command_(max_command) {}

  struct Progress {
    bool complete = false;  // true: command() holds the whole command
    std::uint16_t blocks_received = 0;
  };
  Result<Progress> push(std::span<const std::uint8_t> record);

  // The command completed by the last push (valid until the next push or reset()).
  std::span<const std::uint8_t> command() const noexcept { return command_; }
  bool in_progress() const noexcept { return next_number_ != 0; }
  void reset() noexcept;

 private:
  Result<Progress> fail(std::error_code error) noexcept;

  Direction direction_;
  std::size_t max_command_;
  std::uint16_t next_number_ = 0;
  bool complete_ = false;
  std::vector<std::uint8_t> command_;
};

// Serves a READ answer of any size as blocks of at most 240 bytes ([RS4 manual §5.2.1]): numbers
// 0, 1, … with the last 0xFFFF; an empty answer is one header-only block. The
// flow-control byte is taken at the time each block is produced, with bit 1
// (payload) set from the block's content. max_block_size is clamped to 5..240; the
// answer must not exceed kMaxReadAnswerSize (0x10000 blocks of 236 bytes).
class BlockSplitter {
 public:
  BlockSplitter() = default;
  explicit BlockSplitter(std::vector<std::uint8_t> answer,
                         std::size_t max_block_size = kMaxRecordSize);

  bool done() const noexcept { return done_; }
  std::size_t remaining_blocks() const noexcept;
  // The next block; an empty vector once done().
  std::vector<std::uint8_t> next(FlowControl flow);

 private:
  std::vector<std::uint8_t> answer_;
  std::size_t max_payload_ = kMaxBlockPayload;
  std::size_t offset_ = 0;
  std::uint16_t number_ = 0;
  bool done_ = true;
};

// All blocks of one answer with the same flow state (convenience for tests/tools).
std::vector<std::vector<std::uint8_t>> split_into_blocks(
    std::span<const std::uint8_t> answer, FlowControl flow,
    std::size_t max_block_size = kMaxRecordSize);

}  // namespace rs4sim::rs4::protocol
