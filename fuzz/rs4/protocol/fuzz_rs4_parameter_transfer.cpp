// Fuzzes the proxy's codecs ([docs/proxy-protocol.md]): decode_request (device side), and on
// the master side decode_answer and the answers of PROFI_CMD_PROXY_BEGIN/_END. Whatever decodes
// must encode again, and decoding that encoding gives the same value (decode → encode → decode
// agree); an encoding is canonical (encoding it again gives the same bytes).
#include "rs4/protocol/adapter_answer.h"
#include "rs4/protocol/parameter_transfer.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

using namespace rs4sim::rs4::protocol;

namespace {

void check(bool ok) {
  if (!ok) __builtin_trap();
}

void request_round_trip(std::span<const std::uint8_t> in) {
  const auto first = decode_request(in);
  if (!first) return;
  check(is_transfer_code(in[0]));
  const auto bytes = encode_request(first.value());
  check(static_cast<bool>(bytes));
  check(bytes.value().size() < 1100);
  const auto second = decode_request(bytes.value());
  check(second && second.value() == first.value());
  const auto again = encode_request(second.value());
  check(again && again.value() == bytes.value());
}

void answer_round_trip(std::span<const std::uint8_t> in) {
  const auto first = decode_answer(in);
  if (!first) return;
  check(first.value().status != TransferStatus::kOk || first.value().body.has_value());
  const auto bytes = encode_answer(first.value());
  check(static_cast<bool>(bytes));
  const auto second = decode_answer(bytes.value());
  check(second && second.value() == first.value());
  const auto again = encode_answer(second.value());
  check(again && again.value() == bytes.value());
}

void proxy_answers(std::span<const std::uint8_t> in) {
  if (const auto begin = decode_proxy_begin_answer(in)) {
    const auto bytes = encode_proxy_begin_answer(begin.value());
    check(std::vector<std::uint8_t>(in.begin(), in.end()) == bytes);
  }
  if (const auto end = decode_proxy_end_answer(in)) {
    const auto bytes = encode_proxy_end_answer(end.value());
    check(std::vector<std::uint8_t>(in.begin(), in.end()) == bytes);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);
  request_round_trip(in);
  answer_round_trip(in);
  proxy_answers(in);
  return 0;
}
