// libFuzzer target for the streaming FDL decoder
// ([IEC 61158-4-3 frame formats, FCS, addresses, SAPs, frame reception]). Input byte 0 picks a
// chunk size; the rest is the bus byte stream. Invariants: every delivered telegram re-encodes and
// decodes back to itself; the same stream fed in one chunk and in small chunks gives the same
// telegrams, refused frames and errors; every fed byte is accounted for (delivered, discarded or
// pending); a refused frame has right framing (SD, length, FCS, ED), decode_frame refuses it with
// the same error, and that error follows it; the FCS of the whole input equals its plain byte sum.
#include "dp/fdl/decoder.h"

#include <cstdlib>
#include <optional>
#include <variant>
#include <vector>

namespace {

using rs4sim::dp::fdl::Decoder;
using rs4sim::dp::fdl::DecoderSink;
using rs4sim::dp::fdl::Telegram;

void check(bool ok) {
  if (!ok) std::abort();
}

using Bytes = std::vector<std::uint8_t>;

// SD1 (6 bytes), SD3 (14) or SD2 (LE + 6, LE = LEr, SD repeated), the FCS over DA..DU, ED 16
// [IEC 61158-4-3 frame formats, FCS].
bool framing_is_right(std::span<const std::uint8_t> f) {
  if (f.size() < 6 || f.back() != 0x16) return false;
  std::size_t header = 1;
  if (f[0] == 0x68) {
    if (f[1] != f[2] || f[3] != 0x68 || f.size() != std::size_t{f[1]} + 6) return false;
    header = 4;
  } else if (!(f[0] == 0x10 && f.size() == 6) && !(f[0] == 0xA2 && f.size() == 14)) {
    return false;
  }
  return rs4sim::dp::fdl::frame_check_sequence(f.subspan(header, f.size() - header - 2)) ==
         f[f.size() - 2];
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
  void on_decode_error(std::error_code e) override {
    check(!refused || *refused == e);
    refused.reset();
    events.emplace_back(e);
  }
  void on_refused_frame(std::span<const std::uint8_t> f, std::error_code e) override {
    check(!refused);
    check(framing_is_right(f));
    Telegram back;
    check(rs4sim::dp::fdl::decode_frame(f, back) == e);
    refused = e;
    events.emplace_back(Bytes(f.begin(), f.end()));
  }
  std::vector<std::variant<Telegram, std::error_code, Bytes>> events;
  std::optional<std::error_code> refused;  // until its on_decode_error
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
