#include "rs4/protocol/rs232.h"

namespace rs4sim::rs4::protocol {
namespace {

constexpr std::size_t kMinFrameBody = 3;  // CMD, OPT1, CHK
constexpr unsigned kEndZeros = 3;         // three zeros never occur inside a frame
                                          // ([roboticslibrary/rl LeuzeRs4.cpp])

}  // namespace

std::error_code frame_rs232(std::span<const std::uint8_t> body, std::vector<std::uint8_t>& out) {
  if (body.empty()) return ProtocolError::kEmptyFrame;
  if (body[0] == 0x00 || body[0] == kStuffByte) return ProtocolError::kBadCommandByte;
  out.reserve(out.size() + body.size() + body.size() / 2 + 6);
  out.push_back(0x00);  // start mark
  out.push_back(0x00);
  std::uint8_t check = 0;
  unsigned zeros = 0;
  for (const std::uint8_t byte : body) {
    out.push_back(byte);
    check ^= byte;
    zeros = byte == 0 ? zeros + 1 : 0;
    if (zeros == 2) {  // zero-stuffing: 00 00 → 00 00 FF, counted in the check
      out.push_back(kStuffByte);
      check ^= kStuffByte;
      zeros = 0;
    }
  }
  out.push_back(check == 0 ? kStuffByte : check);  // the check is never 0x00, never stuffed
  out.insert(out.end(), kEndZeros, std::uint8_t{0x00});
  return {};
}

Result<std::vector<std::uint8_t>> frame_rs232(std::span<const std::uint8_t> body) {
  std::vector<std::uint8_t> out;
  if (auto ec = frame_rs232(body, out)) return ec;
  return out;
}

std::vector<Rs232Deframer::Event> Rs232Deframer::feed(std::span<const std::uint8_t> bytes) {
  std::vector<Event> events;
  feed(bytes, events);
  return events;
}

void Rs232Deframer::feed(std::span<const std::uint8_t> bytes, std::vector<Event>& events) {
  for (const std::uint8_t byte : bytes) {
    if (in_frame_) {
      frame_byte(byte, events);
    } else {
      idle_byte(byte);
    }
  }
}

void Rs232Deframer::idle_byte(std::uint8_t byte) {
  if (byte == 0x00) {
    if (zeros_ < kEndZeros) ++zeros_;
    return;
  }
  if (zeros_ >= 2 && byte != kStuffByte) {
    start_frame(byte);
    return;
  }
  // Not a start: a byte after a lost start mark, or `00 00 FF` seen from mid-frame.
  if (zeros_ >= 2) ++counters_.bad_command_bytes;
  ++counters_.garbage_bytes;
  zeros_ = 0;
}

void Rs232Deframer::start_frame(std::uint8_t cmd) {
  in_frame_ = true;
  body_.clear();
  body_.push_back(cmd);
  xor_ = cmd;
  zeros_ = 0;
}

void Rs232Deframer::frame_byte(std::uint8_t byte, std::vector<Event>& events) {
  if (byte == 0x00) {
    if (++zeros_ == kEndZeros) {
      finish_frame(events);
      return;
    }
    body_.push_back(byte);
  } else if (zeros_ == 2) {
    if (byte != kStuffByte) {
      // 00 00 x inside a frame: the frame was cut off and x starts the next one.
      fail(ProtocolError::kStuffingViolation, events);
      start_frame(byte);
      return;
    }
    xor_ ^= byte;  // stuffed 0xFF: counted in the check, dropped from the body
    zeros_ = 0;
    return;
  } else {
    body_.push_back(byte);
    xor_ ^= byte;
    zeros_ = 0;
  }
  if (body_.size() > max_body_ + 1 + 2) fail(ProtocolError::kFrameTooLong, events);
}

void Rs232Deframer::finish_frame(std::vector<Event>& events) {
  body_.resize(body_.size() - 2);  // the first two zeros of the end mark
  if (body_.size() < kMinFrameBody) {
    fail(ProtocolError::kFrameTooShort, events);
  } else {
    const std::uint8_t check = body_.back();
    const auto body_xor = static_cast<std::uint8_t>(xor_ ^ check);
    if (check != (body_xor == 0 ? kStuffByte : body_xor)) {
      fail(ProtocolError::kBadCheck, events);
    } else {
      body_.pop_back();
      ++counters_.frames;
      events.emplace_back(std::move(body_));
      body_ = {};
      in_frame_ = false;
    }
  }
  zeros_ = kEndZeros;  // the end mark also counts as the next start mark
}

void Rs232Deframer::fail(ProtocolError error, std::vector<Event>& events) {
  switch (error) {
    case ProtocolError::kBadCheck: ++counters_.check_errors; break;
    case ProtocolError::kStuffingViolation: ++counters_.stuffing_errors; break;
    case ProtocolError::kFrameTooShort: ++counters_.short_frames; break;
    case ProtocolError::kFrameTooLong: ++counters_.long_frames; break;
    default: break;
  }
  events.emplace_back(make_error_code(error));
  in_frame_ = false;
  body_.clear();
  zeros_ = 0;
}

}  // namespace rs4sim::rs4::protocol
