#include "rs4/rs232/rs232_client.h"

#include "codec/reader.h"
#include "codec/writer.h"

namespace rs4sim::rs4::rs232 {
namespace {

protocol::TelegramPrefix prefix_for(const CommandOptions& options) {
  protocol::TelegramPrefix p;  // option 1 state "none" in messages to the RS4
  p.options.acknowledge = options.acknowledge;
  p.options.password = options.password.has_value();
  if (options.password) p.password = *options.password;
  return p;
}

protocol::Result<Answer> decode_ack(std::span<const std::uint8_t> body) {
  const auto prefix = protocol::decode_prefix(body);
  if (!prefix) return prefix.error();
  codec::Reader r(body.subspan(prefix.value().size));
  Acknowledge a;
  a.positive = body[0] == byte(Rs232Code::kAck);
  a.options = prefix.value().prefix.options;
  a.command = r.u8();
  if (!a.positive) a.error = r.u16_be();
  if (!r.ok()) return protocol::ProtocolError::kTruncated;
  if (!r.at_end()) return protocol::ProtocolError::kTrailingBytes;
  return Answer{a};
}

}  // namespace

std::optional<protocol::Password> make_password(std::string_view ascii) {
  if (ascii.size() > protocol::Password{}.size()) return std::nullopt;
  protocol::Password p;
  p.fill(0xFF);
  for (std::size_t i = 0; i < ascii.size(); ++i) {
    const auto b = static_cast<std::uint8_t>(ascii[i]);
    if (b < 0x20 || b > 0x7E) return std::nullopt;
    p[i] = b;
  }
  return p;
}

std::vector<std::uint8_t> command_body(std::uint8_t code, std::span<const std::uint8_t> data,
                                       const CommandOptions& options) {
  std::vector<std::uint8_t> body;
  (void)protocol::encode_prefix(code, prefix_for(options), body);  // no field pair: no error
  body.insert(body.end(), data.begin(), data.end());
  return body;
}

protocol::Result<std::vector<std::uint8_t>> encode_command(std::uint8_t code,
                                                           std::span<const std::uint8_t> data,
                                                           const CommandOptions& options) {
  return protocol::frame_rs232(command_body(code, data, options));
}

protocol::Result<std::vector<std::uint8_t>> encode_set_baud(std::uint32_t baud,
                                                            const CommandOptions& options) {
  const auto code = baud_code(baud);
  if (!code) return protocol::ProtocolError::kBadAnswerValue;
  const std::array<std::uint8_t, 2> data{static_cast<std::uint8_t>(*code >> 8),
                                         static_cast<std::uint8_t>(*code & 0xFF)};
  return encode_command(byte(Rs232Code::kSetBaud), data, options);
}

protocol::Result<std::vector<std::uint8_t>> encode_measurement_window(
    std::uint8_t resolution, std::uint16_t start, std::uint16_t stop,
    const CommandOptions& options) {
  std::vector<std::uint8_t> data;
  codec::Appender w(data);
  w.u8(resolution);
  w.u16_be(start);
  w.u16_be(stop);
  return encode_command(byte(Rs232Code::kMeasurementWindow), data, options);
}

protocol::Result<std::vector<std::uint8_t>> encode_stream_control(bool on,
                                                                  const CommandOptions& options) {
  const std::array<std::uint8_t, 1> data{static_cast<std::uint8_t>(on ? 1 : 0)};
  return encode_command(byte(Rs232Code::kStreamControl), data, options);
}

protocol::Result<std::vector<std::uint8_t>> encode_transfer(
    const protocol::TransferRequest& request, const CommandOptions& options) {
  auto body = protocol::encode_request(request, prefix_for(options));
  if (!body) return body.error();
  return protocol::frame_rs232(body.value());
}

protocol::Result<Answer> decode_answer(std::span<const std::uint8_t> body) {
  if (body.empty()) return protocol::ProtocolError::kTruncated;
  if (body[0] == byte(Rs232Code::kAck) || body[0] == byte(Rs232Code::kNak)) return decode_ack(body);
  if (protocol::is_transfer_code(body[0])) {
    auto a = protocol::decode_answer(body);
    if (!a) return a.error();
    return Answer{std::move(a.value())};
  }
  auto t = protocol::decode_telegram(body);
  if (!t) return t.error();
  return std::visit([](auto& telegram) { return Answer{std::move(telegram)}; }, t.value());
}

std::vector<protocol::Result<Answer>> AnswerReader::feed(std::span<const std::uint8_t> bytes) {
  std::vector<protocol::Result<Answer>> out;
  for (auto& event : deframer_.feed(bytes)) {
    if (!event) {
      out.emplace_back(event.error());
    } else {
      out.push_back(decode_answer(event.value()));
    }
  }
  return out;
}

}  // namespace rs4sim::rs4::rs232
