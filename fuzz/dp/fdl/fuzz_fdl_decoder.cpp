// libFuzzer target for the streaming FDL decoder
// ([IEC 61158-4-3 frame formats, FCS, addresses, SAPs, frame reception]). Input byte 0 picks a
// chunk size; the rest is the bus byte stream. Invariants: every delivered telegram re-encodes and
// decodes back to itself; the same stream fed in one chunk and in small chunks gives the same
// telegrams and errors; every fed byte is accounted for (delivered, discarded or pending); the FCS
// of the whole input equals its plain byte sum.
#include "dp/fdl/decoder.h"

#include <cstdlib>
#include <variant>
#include <vector>

namespace {

using rs4sim::dp::fdl::Decoder;
using rs4sim::dp::fdl::DecoderSink;
using rs4sim::dp::fdl::Telegram;

void check(bool ok) {
  if (!ok) std::abort();
}

class CheckingSink final : public DecoderSink {
 public:
  void on_telegram(const Telegram& t) override {
    frame.clear();
    const std::size_t n = rs4sim::dp::fdl::encode(t, frame);
    check(n == rs4sim::dp::fdl::encoded_size(t));
    Telegram back;
    check(!rs4sim::dp::fdl::decode_frame(frame, back));
    check(back == t);
    delivered_bytes += n;
    events.emplace_back(t);
  }
  void on_decode_error(std::error_code e) override { events.emplace_back(e); }
  std::vector<std::variant<Telegram, std::error_code>> events;
  std::vector<std::uint8_t> frame;
  std::size_t delivered_bytes = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t chunk = (data[0] % 32) + 1;
  const std::span<const std::uint8_t> stream(data + 1, size - 1);

  Decoder whole;
  CheckingSink a;
  whole.feed(stream, a);
  Decoder pieces;
  CheckingSink b;
  for (std::size_t pos = 0; pos < stream.size(); pos += chunk) {
    pieces.feed(stream.subspan(pos, std::min(chunk, stream.size() - pos)), b);
  }
  check(a.events == b.events);
  check(whole.pending_bytes() == pieces.pending_bytes());
  check(a.delivered_bytes + whole.stats().discarded_bytes + whole.pending_bytes() == stream.size());
  whole.idle(a);
  check(whole.pending_bytes() == 0);
  // The word-wise FCS equals the plain byte sum at every length and alignment.
  unsigned sum = 0;
  for (const std::uint8_t byte : stream) sum += byte;
  check(rs4sim::dp::fdl::frame_check_sequence(stream) == static_cast<std::uint8_t>(sum));
  return 0;
}
