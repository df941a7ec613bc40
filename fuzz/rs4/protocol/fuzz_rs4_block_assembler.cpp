// Fuzzes the WRITE-side block assembler ([RS4 manual §5.2.1]) with a stream of
// records, and checks splitter → READ assembler round trips on the same bytes.
// Input: [n][n record bytes][n][…] — each record is preceded by its size byte.
#include "rs4/protocol/adapter_command.h"
#include "rs4/protocol/block.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

using namespace rs4sim::rs4::protocol;

namespace {

void check(bool ok) {
  if (!ok) __builtin_trap();
}

void round_trip(std::span<const std::uint8_t> data) {
  const FlowControl flow{true, false, FlowState::kNormal};
  const auto blocks = split_into_blocks(data, flow);
  BlockAssembler reader(Direction::kRead);
  for (const auto& block : blocks) {
    check(block.size() <= kMaxRecordSize);
    auto p = reader.push(block);
    check(static_cast<bool>(p));
  }
  check(std::equal(data.begin(), data.end(), reader.command().begin(), reader.command().end()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);
  BlockAssembler writer;
  std::size_t at = 0;
  while (at < input.size()) {
    const std::size_t n = std::min<std::size_t>(input[at], input.size() - at - 1);
    const auto record = input.subspan(at + 1, n);
    at += 1 + n;
    if (auto read = decode_block(record, Direction::kRead)) {
      const BlockHeader& h = read.value().header;
      check(read.value().payload.size() + kBlockHeaderSize == h.length);
      if (auto flow = decode_flow_control(h.flow_control)) {
        check(encode_flow_control(flow.value()) == h.flow_control);
      }
    }
    auto progress = writer.push(record);
    if (!progress) continue;
    check(writer.command().size() <= kMaxCommandSize);
    if (progress.value().complete) {
      auto command = parse_write_command(writer.command());
      check(static_cast<bool>(command) == !writer.command().empty());
    }
  }
  if (input.size() <= 2 * kMaxCommandSize) round_trip(input);
  return 0;
}
