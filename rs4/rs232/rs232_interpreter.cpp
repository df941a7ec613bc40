// Rs232Port: the command interpreter of the RS4's RS232 interface ([docs/rs232.md]).
//
// Rules (DECISION, docs/rs232.md "Reactions"):
//  - a command with OPT1 bit 6 gets 0x16 (code) before its answer, or 0x17 (code, error)
//    instead of it ([roboticslibrary/rl LeuzeRs4.cpp]); without bit 6 a refusal is answered
//    0x53 (error, parameter, 0x0005) and a setting command has no answer;
//  - the commands that change the scanner (0x10, 0x20, 0x62..0x65) need OPT1 bit 5 and a
//    password the RS4 accepts ([RS4 manual §3]: a password guards the safety settings).
#include "codec/reader.h"
#include "codec/writer.h"
#include "rs4/adapter/rs4_commands.h"
#include "rs4/protocol/measurement.h"
#include "rs4/protocol/parameter_transfer.h"
#include "rs4/rs232/rs232_port.h"
#include "rs4/scanner/parameter_codec.h"

#include <algorithm>

namespace rs4sim::rs4::rs232 {
namespace {

using protocol::TransferCode;

bool protected_command(std::uint8_t code) noexcept {
  return code == byte(Rs232Code::kCheckPassword) || code == byte(Rs232Code::kMeasurementWindow) ||
         (protocol::is_transfer_code(code) &&
          code >= static_cast<std::uint8_t>(TransferCode::kDownloadBegin));
}

bool empty_password(const scanner::Password& p) {
  return std::all_of(p.begin(), p.end(), [](std::uint8_t b) { return b == 0xFF; });
}

std::vector<std::uint8_t> prefix_of(std::uint8_t code, const scanner::Scanner& rs4) {
  std::vector<std::uint8_t> out;
  (void)protocol::encode_prefix(code, adapter::rs4_prefix(rs4), out);  // options from the model
  return out;
}

}  // namespace

bool Rs232Port::password_ok(const protocol::TelegramPrefix& prefix) const {
  if (!prefix.options.password) return false;
  const auto& user = adapter_.scanner().parameters().passwords;
  if (std::all_of(user.begin(), user.end(), empty_password)) {
    return prefix.password == options_.factory_password;
  }
  return std::any_of(user.begin(), user.end(), [&](const scanner::Password& p) {
    return !empty_password(p) && p == prefix.password;
  });
}

void Rs232Port::interpret(std::span<const std::uint8_t> body, stream::TimePoint now) {
  ++counters_.commands;
  const std::uint8_t code = body[0];  // the deframer delivers ≥ 2 bytes
  const auto prefix = protocol::decode_prefix(body);
  if (!prefix) {
    refuse(code, false, {kErrorBadData, code}, now);
    return;
  }
  const bool ack = prefix.value().prefix.options.acknowledge;
  if (protected_command(code) && !password_ok(prefix.value().prefix)) {
    ++counters_.wrong_passwords;
    refuse(code, ack, {kErrorWrongPassword, code}, now);
    return;
  }
  const auto data = body.subspan(prefix.value().size);
  answer_.reset();
  const Verdict v = execute(code, data, body, now);
  if (v.error != 0) {
    refuse(code, ack, v, now);
    return;
  }
  if (ack) acknowledge(code, now);
  if (answer_) send(std::move(*answer_), now);
  answer_.reset();
  if (pending_line_) pending_line_at_ = std::max(now, line_busy_until_);
}

Rs232Port::Verdict Rs232Port::execute(std::uint8_t code, std::span<const std::uint8_t> data,
                                      std::span<const std::uint8_t> body, stream::TimePoint now) {
  auto& rs4 = adapter_.scanner();
  if (protocol::is_transfer_code(
          code)) {  // one definition with PROFIBUS ([docs/proxy-protocol.md])
    answer_ = session_.answer(body, rs4, now);
    adapter_.on_time(now);  // a committed set: the adapter sees the scanner's new state
    return {};
  }
  switch (code) {
    case byte(Rs232Code::kCheckPassword):
      return data.empty() ? Verdict{} : Verdict{kErrorBadData, code};
    case byte(Rs232Code::kAlive):
      if (!data.empty()) return {kErrorBadData, code};
      answer_ = adapter::alive_telegram(rs4);
      return {};
    case byte(Rs232Code::kRequestScan):
      if (!data.empty()) return {kErrorBadData, code};
      if (rs4.status().scan_counter == 0 ||
          (rs4.status().state != scanner::ScannerState::kMeasuring &&
           rs4.status().state != scanner::ScannerState::kError)) {
        return {adapter::kRs4ErrorNoScan, static_cast<std::uint16_t>(rs4.status().state)};
      }
      ++counters_.measurements;
      answer_ = adapter::measurement_telegram(rs4);
      return {};
    case byte(Rs232Code::kStreamControl):
      if (data.size() != 1 || data[0] > 1) return {kErrorBadData, code};
      streaming_ = data[0] == 1;
      streamed_scan_ = rs4.status().scan_counter != 0
                           ? std::optional<std::uint32_t>(rs4.last_scan().scan_number)
                           : std::nullopt;
      return {};
    case byte(Rs232Code::kSetBaud): return set_baud(data, now);
    case byte(Rs232Code::kMeasurementWindow): return set_window(data, now);
    default: break;
  }
  // [RS4 manual §5.2.2]: a command the RS4 does not know is answered with an error.
  return {adapter::kRs4ErrorUnknownCommand, code};
}

// 0x19: u16 rate code. The new rate applies once the acknowledgement (if requested) has
// left the line at the old rate; the link re-reads line_settings() after on_time().
Rs232Port::Verdict Rs232Port::set_baud(std::span<const std::uint8_t> data, stream::TimePoint now) {
  codec::Reader r(data);
  const std::uint16_t code = r.u16_be();
  const auto baud = baud_of_code(code);
  if (!r.ok() || !r.at_end() || !baud) return {kErrorBadData, byte(Rs232Code::kSetBaud)};
  pending_line_ = line_8n1(*baud);
  pending_line_at_ = now;
  return {};
}

// 0x20: resolution u8, start u16, stop u16 ([RS4 manual §5.2.3.4]) into the parameter set, in the
// scanner's configuration mode like every change of the set ([RS4 manual §7.1.2]).
Rs232Port::Verdict Rs232Port::set_window(std::span<const std::uint8_t> data,
                                         stream::TimePoint now) {
  constexpr auto kCode = byte(Rs232Code::kMeasurementWindow);
  codec::Reader r(data);
  scanner::MeasurementOutput m;
  m.resolution = r.u8();
  m.start = r.u16_be();
  m.stop = r.u16_be();
  if (!r.ok() || !r.at_end() || !protocol::measurement_value_count(m.start, m.stop, m.resolution)) {
    return {kErrorBadData, kCode};
  }
  auto& rs4 = adapter_.scanner();
  auto set = rs4.parameters();
  set.measurement = m;
  if (scanner::validate(set)) return {kErrorBadData, kCode};
  if (!rs4.enter_configuration(now)) {
    return {kErrorNotOperational, static_cast<std::uint16_t>(rs4.status().state)};
  }
  const bool applied = static_cast<bool>(rs4.set_parameters(set, now));
  (void)rs4.leave_configuration(now);
  adapter_.on_time(now);
  return applied ? Verdict{} : Verdict{kErrorBadData, kCode};
}

void Rs232Port::refuse(std::uint8_t code, bool acknowledge_requested, const Verdict& v,
                       stream::TimePoint now) {
  const auto& rs4 = adapter_.scanner();
  if (acknowledge_requested) {
    ++counters_.naks;
    auto body = prefix_of(byte(Rs232Code::kNak), rs4);
    codec::Appender w(body);
    w.u8(code);
    w.u16_be(v.error);
    send(std::move(body), now);
    return;
  }
  ++counters_.error_telegrams;
  send(adapter::error_telegram(rs4, v.error, v.parameter, adapter::kRs4ErrorFunctionCommands), now);
}

void Rs232Port::acknowledge(std::uint8_t code, stream::TimePoint now) {
  ++counters_.acks;
  auto body = prefix_of(byte(Rs232Code::kAck), adapter_.scanner());
  body.push_back(code);
  send(std::move(body), now);
}

}  // namespace rs4sim::rs4::rs232
