// Streaming FDL receiver, [IEC 61158-4-3 frame formats, FCS, addresses, SAPs] and the receiver
// checklist [IEC 61158-4-3 frame reception].
#include "dp/fdl/decoder.h"

#include <algorithm>
#include <cstring>

namespace rs4sim::dp::fdl {
namespace {

constexpr std::uint8_t kExtensionBit = 0x80;
constexpr std::uint8_t kMinLe = 3;    // DA SA FC ([IEC 61158-4-3 frame reception]: reject LE < 3)
constexpr std::uint8_t kMaxLe = 249;  // [IEC 61158-4-3 frame formats]

static_assert(static_cast<std::size_t>(DecodeError::kTruncated) == kDecodeErrorKinds,
              "DecoderStats::errors is indexed by DecodeError");

bool is_start_delimiter(std::uint8_t b) {
  return b == kSd1 || b == kSd2 || b == kSd3 || b == kSd4 || b == kSc;
}

// [IEC 61158-4-3 frame control]: request codes 0,3,4,5,6,7,9,C,D,E,F; response codes
// 0,1,2,3,8,9,A,C,D. Bit 7 only for a clock value (request, function 0).
bool valid_frame_control(std::uint8_t fc) {
  constexpr std::uint16_t kRequestCodes = 0xF2F9;   // bits 0,3,4,5,6,7,9,12,13,14,15
  constexpr std::uint16_t kResponseCodes = 0x370F;  // bits 0,1,2,3,8,9,10,12,13
  const unsigned code = fc & 0x0FU;
  if ((fc & 0x40U) != 0) {
    if ((fc & 0x80U) != 0 && code != 0) return false;
    return ((kRequestCodes >> code) & 1U) != 0;
  }
  if ((fc & 0x80U) != 0) return false;
  return ((kResponseCodes >> code) & 1U) != 0;
}

// DP uses exactly one extension byte per address whose bits 7 and 6 are 0
// ([IEC 61158-4-3 addresses, SAPs]).
bool valid_sap_byte(std::uint8_t b) { return (b & 0xC0U) == 0; }

}  // namespace

std::uint64_t DecoderStats::total_errors() const {
  std::uint64_t sum = 0;
  for (const auto n : errors) sum += n;
  return sum;
}

void Decoder::feed(std::span<const std::uint8_t> bytes, DecoderSink& sink) {
  stats_.bytes += bytes.size();
  while (!bytes.empty()) {
    if (len_ == 0) {
      // Fast path: decode straight from the caller's bytes; keep only an incomplete tail.
      const std::size_t used = run(bytes, sink);
      bytes = bytes.subspan(used);
      if (!bytes.empty()) [[unlikely]]
        std::memcpy(buf_.data(), bytes.data(), bytes.size());
      len_ = bytes.size();
      return;
    }
    const std::size_t take = std::min(bytes.size(), buf_.size() - len_);
    std::memcpy(buf_.data() + len_, bytes.data(), take);
    len_ += take;
    bytes = bytes.subspan(take);
    const std::size_t used = run(Bytes(buf_.data(), len_), sink);
    len_ -= used;
    std::memmove(buf_.data(), buf_.data() + used, len_);
  }
}

bool decodes_as_itself(const Telegram& t) {
  const bool bare = t.fc.raw == 0 && !t.dsap && !t.ssap && t.data.empty();
  switch (t.type) {
    case FrameType::kShortAck: return bare && t.da == 0 && t.sa == 0;  // E5 alone
    case FrameType::kToken: return bare;                                // SD4 DA SA
    case FrameType::kSd1:
    case FrameType::kSd2:
    case FrameType::kSd3: return valid_frame_control(t.fc.raw);
  }
  return false;
}

void Decoder::feed_encoded(const Telegram& t, DecoderSink& sink) {
  if (len_ != 0 || !decodes_as_itself(t)) [[unlikely]] {
    std::array<std::uint8_t, kMaxTelegramSize> wire;  // the general path: the bytes
    feed(Bytes(wire.data(), encode(t, std::span<std::uint8_t>(wire))), sink);
    return;
  }
  // What feed() would count for the frame: its bytes and one telegram; the frame ends any
  // garbage run.
  const std::size_t du = t.data.size() + (t.dsap ? 2U : 0U);
  switch (t.type) {
    case FrameType::kShortAck: stats_.bytes += 1; break;
    case FrameType::kToken: stats_.bytes += 3; break;
    case FrameType::kSd1: stats_.bytes += 6; break;
    case FrameType::kSd3: stats_.bytes += 14; break;
    case FrameType::kSd2: stats_.bytes += du + 9; break;
  }
  in_garbage_ = false;
  ++stats_.telegrams;
  sink.on_telegram(t);
}

void Decoder::idle(DecoderSink& sink) {
  if (len_ == 0) return;
  stats_.discarded_bytes += len_;
  len_ = 0;
  in_garbage_ = false;
  ++stats_.errors[static_cast<std::size_t>(DecodeError::kTruncated)];
  sink.on_decode_error(DecodeError::kTruncated);
}

void Decoder::reset() {
  len_ = 0;
  in_garbage_ = false;
}

[[gnu::always_inline]] inline std::size_t Decoder::run(Bytes v, DecoderSink& sink) {
  std::size_t used = 0;
  while (used < v.size()) {
    const std::size_t n = step(v.subspan(used), sink);
    if (n == 0) break;
    used += n;
  }
  return used;
}

// step, parse_sd2 and deliver are one straight path for the common telegram: inlined into
// run() so that no register saves or calls separate the checks (errors are out of line).
[[gnu::always_inline]] inline std::size_t Decoder::step(Bytes v, DecoderSink& sink) {
  switch (v[0]) {
    case kSc:
      in_garbage_ = false;
      out_ = Telegram{};
      out_.type = FrameType::kShortAck;
      ++stats_.telegrams;
      sink.on_telegram(out_);
      return 1;
    case kSd1: return parse_fixed(v, 6, sink);
    case kSd3: return parse_fixed(v, 14, sink);
    case kSd2: return parse_sd2(v, sink);
    case kSd4: return parse_token(v, sink);
    default: return skip_garbage(v, sink);
  }
}

std::size_t Decoder::skip_garbage(Bytes v, DecoderSink& sink) {
  const auto it = std::find_if(v.begin(), v.end(), is_start_delimiter);
  const auto n = static_cast<std::size_t>(it - v.begin());
  stats_.discarded_bytes += n;
  if (!in_garbage_) {
    in_garbage_ = true;
    ++stats_.errors[static_cast<std::size_t>(DecodeError::kGarbage)];
    sink.on_decode_error(DecodeError::kGarbage);
  }
  return n;
}

// Reports `e` and drops `drop` bytes. Bytes after a rejected start delimiter that are no
// start delimiter belong to the rejected frame: they are skipped without a second error.
[[gnu::cold, gnu::noinline]] std::size_t Decoder::reject(DecodeError e, std::size_t drop,
                                                         DecoderSink& sink) {
  ++stats_.errors[static_cast<std::size_t>(e)];
  stats_.discarded_bytes += drop;
  in_garbage_ = true;
  sink.on_decode_error(e);
  return drop;
}

// A frame with confirmed framing whose content is refused: the sink sees its bytes, then the
// error; the whole frame is dropped.
[[gnu::cold, gnu::noinline]] std::size_t Decoder::refuse(DecodeError e, Bytes frame,
                                                         DecoderSink& sink) {
  sink.on_refused_frame(frame, e);
  return reject(e, frame.size(), sink);
}

std::size_t Decoder::parse_token(Bytes v, DecoderSink& sink) {
  if (v.size() < 3) return 0;
  if (((v[1] | v[2]) & kExtensionBit) != 0) return reject(DecodeError::kBadTokenAddress, 1, sink);
  in_garbage_ = false;
  out_ = Telegram{};
  out_.type = FrameType::kToken;
  out_.da = v[1];
  out_.sa = v[2];
  ++stats_.telegrams;
  sink.on_telegram(out_);
  return 3;
}

std::size_t Decoder::parse_fixed(Bytes v, std::size_t frame_len, DecoderSink& sink) {
  if (v.size() < frame_len) return 0;
  if (v[frame_len - 1] != kEd) return reject(DecodeError::kBadEndDelimiter, 1, sink);
  if (frame_check_sequence(v.subspan(1, frame_len - 3)) != v[frame_len - 2]) {
    return reject(DecodeError::kBadFcs, frame_len, sink);
  }
  return deliver(v.first(frame_len), 1, sink);
}

[[gnu::always_inline]] inline std::size_t Decoder::parse_sd2(Bytes v, DecoderSink& sink) {
  if (v.size() >= 2 && (v[1] < kMinLe || v[1] > kMaxLe)) {
    return reject(DecodeError::kLengthOutOfRange, 1, sink);
  }
  if (v.size() >= 3 && v[2] != v[1]) return reject(DecodeError::kLengthMismatch, 1, sink);
  if (v.size() >= 4 && v[3] != kSd2) return reject(DecodeError::kStartDelimiterMismatch, 1, sink);
  if (v.size() < 4) return 0;
  const std::size_t frame_len = std::size_t{v[1]} + 6;
  if (v.size() < frame_len) return 0;
  if (v[frame_len - 1] != kEd) return reject(DecodeError::kBadEndDelimiter, 1, sink);
  if (frame_check_sequence(v.subspan(4, v[1])) != v[frame_len - 2]) {
    return reject(DecodeError::kBadFcs, frame_len, sink);
  }
  return deliver(v.first(frame_len), 4, sink);
}

// `frame` is SD…ED with correct length, FCS and ED; `header_len` bytes precede DA.
// Semantic errors drop the whole frame: its framing is confirmed.
[[gnu::always_inline]] inline std::size_t Decoder::deliver(Bytes frame, std::size_t header_len,
                                                           DecoderSink& sink) {
  const std::uint8_t da = frame[header_len];
  const std::uint8_t sa = frame[header_len + 1];
  const std::uint8_t fc = frame[header_len + 2];
  Bytes du = frame.subspan(header_len + 3, frame.size() - header_len - 5);
  if (!valid_frame_control(fc)) return refuse(DecodeError::kBadFrameControl, frame, sink);
  const bool has_dsap = (da & kExtensionBit) != 0;
  const bool has_ssap = (sa & kExtensionBit) != 0;
  const std::size_t ext = (has_dsap ? 1U : 0U) + (has_ssap ? 1U : 0U);
  if (du.size() < ext) return refuse(DecodeError::kBadAddressExtension, frame, sink);
  if (has_dsap && !valid_sap_byte(du[0])) {
    return refuse(DecodeError::kBadAddressExtension, frame, sink);
  }
  if (has_ssap && !valid_sap_byte(du[ext - 1])) {
    return refuse(DecodeError::kBadAddressExtension, frame, sink);
  }
  if (has_dsap != has_ssap) return refuse(DecodeError::kSapWithoutPartner, frame, sink);
  in_garbage_ = false;
  out_.type = frame[0] == kSd1   ? FrameType::kSd1
              : frame[0] == kSd2 ? FrameType::kSd2
                                 : FrameType::kSd3;
  out_.da = static_cast<std::uint8_t>(da & 0x7FU);
  out_.sa = static_cast<std::uint8_t>(sa & 0x7FU);
  out_.fc = FrameControl{fc};
  out_.dsap = has_dsap ? std::optional<std::uint8_t>(du[0]) : std::nullopt;
  out_.ssap = has_ssap ? std::optional<std::uint8_t>(du[ext - 1]) : std::nullopt;
  du = du.subspan(ext);
  // One memcpy instead of static_vector::assign's element loop; no zero-fill first.
  out_.data.resize(du.size(), boost::container::default_init);
  if (!du.empty()) std::memcpy(out_.data.data(), du.data(), du.size());
  ++stats_.telegrams;
  sink.on_telegram(out_);
  return frame.size();
}

namespace {

class SingleFrameSink final : public DecoderSink {
 public:
  explicit SingleFrameSink(Telegram& out) : out_(out) {}
  void on_telegram(const Telegram& t) override {
    if (!got_ && !error_) out_ = t;
    got_ = true;
  }
  void on_decode_error(std::error_code e) override {
    if (!error_ && !got_) error_ = e;
  }
  bool got_ = false;
  std::error_code error_;

 private:
  Telegram& out_;
};

}  // namespace

std::error_code decode_frame(std::span<const std::uint8_t> frame, Telegram& out) {
  Decoder decoder;
  SingleFrameSink sink(out);
  decoder.feed(frame, sink);
  if (sink.error_) return sink.error_;
  if (!sink.got_ || decoder.pending_bytes() != 0) return DecodeError::kTruncated;
  if (decoder.stats().telegrams != 1 || decoder.stats().total_errors() != 0) {
    return DecodeError::kGarbage;  // trailing bytes after the frame
  }
  return {};
}

}  // namespace rs4sim::dp::fdl
