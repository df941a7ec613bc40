#pragma once
// Streaming FDL receiver: byte chunks in, telegrams or typed errors out
// ([IEC 61158-4-3 frame formats, FCS, addresses, SAPs, frame reception]).
//
// Chunks may split or merge frames arbitrarily. On a malformed frame the decoder reports
// one DecodeError and rescans from the byte after the rejected start delimiter, so a good
// telegram that follows (or hides inside the rejected bytes) is not lost. Exception: a
// frame whose header, length and ED are right but whose FCS, FC or SAP bytes are wrong is
// dropped as a whole (its framing is confirmed by the ED), so data bytes such as 0xE5
// inside it are not misread as short acknowledgements. No heap allocation per telegram:
// complete frames are decoded in place from the caller's bytes, only an incomplete tail is
// copied into the member buffer, and the output telegram is a member.

#include "dp/fdl/errors.h"
#include "dp/fdl/telegram.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <system_error>

namespace rs4sim::dp::fdl {

// Receives the decoder's output. The calls happen inside Decoder::feed()/idle(); the
// telegram reference and the frame bytes are only valid during the call.
class DecoderSink {
 public:
  virtual ~DecoderSink() = default;
  virtual void on_telegram(const Telegram& t) = 0;
  virtual void on_decode_error(std::error_code /*e*/) {}
  // A frame whose framing is right (start delimiter, length, FCS and end delimiter
  // [IEC 61158-4-3 frame formats, FCS]) but whose content a DP receiver refuses: a reserved
  // FC code (kBadFrameControl), an address extension DP does not use, such as a segment
  // address (kBadAddressExtension), or a DSAP without an SSAP (kSapWithoutPartner)
  // [IEC 61158-4-3 frame control, addresses, SAPs]. `frame` is the whole frame, SD to ED.
  // Called just before on_decode_error(e) for the same frame. A station has no use for it;
  // a sniffer that shows everything on the line keeps the frame.
  virtual void on_refused_frame(std::span<const std::uint8_t> /*frame*/, std::error_code /*e*/) {}
};

struct DecoderStats {
  std::uint64_t bytes = 0;            // bytes fed
  std::uint64_t telegrams = 0;        // telegrams delivered
  std::uint64_t discarded_bytes = 0;  // bytes dropped as garbage or as part of a bad frame
  std::array<std::uint64_t, kDecodeErrorKinds + 1> errors{};  // indexed by DecodeError

  [[nodiscard]] std::uint64_t count(DecodeError e) const {
    return errors[static_cast<std::size_t>(e)];
  }
  [[nodiscard]] std::uint64_t total_errors() const;
};

class Decoder {
 public:
  // Feeds received bytes; delivers every complete telegram and every error to `sink`.
  void feed(std::span<const std::uint8_t> bytes, DecoderSink& sink);

  // Feeds the frame fdl::encode(t) would give, for a link that encoded `t` itself and knows
  // nothing changed the bytes since (the memory bus, for a frame no fault touched): the sink
  // gets exactly what feed() of those bytes would give, and the statistics count the same.
  // When `t` decodes as itself (decodes_as_itself) and no partial frame is pending, that is
  // `t`, delivered without parsing the bytes again; otherwise the bytes are encoded here and
  // go through feed(), so every receiver check that encode() does not make (the FC code, a
  // short acknowledgement or token carrying other fields) still runs. Precondition: `t`
  // can be encoded (the link encoded it before; encode() throws otherwise).
  void feed_encoded(const Telegram& t, DecoderSink& sink);

  // The line has been idle for ≥ TSYN ([IEC 61158-4-3 bus parameters, timing]): a partial frame is
  // reported as kTruncated and dropped. Links with idle detection call this; others never need to.
  void idle(DecoderSink& sink);

  // Drops any partial frame without reporting it (e.g. link re-opened).
  void reset();

  [[nodiscard]] const DecoderStats& stats() const { return stats_; }
  [[nodiscard]] std::size_t pending_bytes() const { return len_; }

 private:
  using Bytes = std::span<const std::uint8_t>;
  // Each step looks at the front of `v` and returns how many bytes it consumed
  // (0 = an incomplete frame, more bytes needed).
  std::size_t step(Bytes v, DecoderSink& sink);
  std::size_t parse_fixed(Bytes v, std::size_t frame_len, DecoderSink& sink);
  std::size_t parse_sd2(Bytes v, DecoderSink& sink);
  std::size_t parse_token(Bytes v, DecoderSink& sink);
  std::size_t skip_garbage(Bytes v, DecoderSink& sink);
  std::size_t reject(DecodeError e, std::size_t drop, DecoderSink& sink);
  std::size_t refuse(DecodeError e, Bytes frame, DecoderSink& sink);
  std::size_t deliver(Bytes frame, std::size_t header_len, DecoderSink& sink);
  std::size_t run(Bytes v, DecoderSink& sink);  // steps until 0; returns bytes consumed

  std::array<std::uint8_t, 2 * kMaxTelegramSize> buf_{};
  std::size_t len_ = 0;
  bool in_garbage_ = false;  // the bytes being skipped already produced their error
  Telegram out_;
  DecoderStats stats_;
};

// True when decoding fdl::encode(t) gives one telegram equal to `t` (Decoder::feed_encoded's
// fast path): the receiver checks of [IEC 61158-4-3 frame reception] that encode() does not
// make pass (the FC is a defined request or response code), and a short acknowledgement or
// token carries nothing the wire drops. Precondition: `t` can be encoded.
bool decodes_as_itself(const Telegram& t);

// Decodes one complete frame (exactly SD…ED, or E5, or SD4) into `out`. For tests, tools
// and the fuzzer's round-trip check; links use Decoder.
std::error_code decode_frame(std::span<const std::uint8_t> frame, Telegram& out);

}  // namespace rs4sim::dp::fdl
