// Rs232Port: the command interpreter of the RS4's RS232 interface ([docs/rs232.md]).
//
// Rules (DECISION, docs/rs232.md "Reactions"): the RS4 command set of
// rs4/adapter/rs4_commands.h, one for this port and the PROFIBUS tunnel ([RS4 manual §5.2.1]
// "Alle Kommandos werden transparent von und zur RS232 des RS4 übertragen"):
//  - a command with OPT1 bit 6 gets 0x16 (code) before its answer, or 0x17 (code, error)
//    instead of it ([roboticslibrary/rl LeuzeRs4.cpp]); without bit 6 a refusal is answered
//    0x53 (error, parameter, 0x0005) and a setting command has no answer;
//  - the commands that change the scanner (0x10, 0x20, 0x62..0x65) need OPT1 bit 5 and a
//    password the RS4 accepts (adapter::password_accepted);
//  - an unknown command puts the RS4 into its error state ([RS4 manual §5.2.2] "RS4 geht in
//    Fehlerzustand"), as over PROFIBUS.
#include "codec/reader.h"
#include "rs4/adapter/rs4_commands.h"
#include "rs4/protocol/parameter_transfer.h"
#include "rs4/rs232/rs232_port.h"

namespace rs4sim::rs4::rs232 {

bool Rs232Port::password_ok(const protocol::TelegramPrefix& prefix) const {
  return adapter::password_accepted(adapter_.scanner().parameters(), prefix,
                                    options_.factory_password);
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
  if (adapter::protected_command(code) && !password_ok(prefix.value().prefix)) {
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
  if (adapter::setting_command(code)) {
    const auto v = adapter::execute_setting(rs4, code, data, now);
    if (!v.ok()) return {v.error, v.parameter};
    if (code == adapter::kRs4SetBaud) return set_baud(data, now);
    if (code == adapter::kRs4StreamControl) {
      streaming_ = data[0] == 1;
      streamed_scan_ = rs4.status().scan_counter != 0
                           ? std::optional<std::uint32_t>(rs4.last_scan().scan_number)
                           : std::nullopt;
    }
    adapter_.on_time(now);  // a new window: the adapter sees the scanner's configuration pass
    return {};
  }
  switch (code) {
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
    default: break;
  }
  // [RS4 manual §5.2.2]: a command the RS4 does not know is answered with an error.
  return {adapter::kRs4ErrorUnknownCommand, code};
}

// 0x19 (data checked by adapter::execute_setting): the new rate applies once the
// acknowledgement (if requested) has left the line at the old rate; the link re-reads
// line_settings() after on_time().
Rs232Port::Verdict Rs232Port::set_baud(std::span<const std::uint8_t> data, stream::TimePoint now) {
  codec::Reader r(data);
  const auto baud = baud_of_code(r.u16_be());
  if (!r.ok() || !baud) return {kErrorBadData, byte(Rs232Code::kSetBaud)};
  pending_line_ = line_8n1(*baud);
  pending_line_at_ = now;
  return {};
}

// An unknown command puts the RS4 into its error state ([RS4 manual §5.2.2], as behind the
// PROFIBUS tunnel): the error telegram it sends for it is its own error event (0x0501, the
// command byte, 0x0005), after the 0x17 when an acknowledge was asked for; while that error is
// still latched the RS4 raises no new event and the refusal is sent as for any other.
void Rs232Port::refuse(std::uint8_t code, bool acknowledge_requested, const Verdict& v,
                       stream::TimePoint now) {
  auto& rs4 = adapter_.scanner();
  if (acknowledge_requested) {
    ++counters_.naks;
    send(adapter::nak_telegram(rs4, code, v.error), now);
  }
  const auto events = counters_.events;
  if (v.error == adapter::kRs4ErrorUnknownCommand) {
    rs4.unknown_command(code, now);
    adapter_.on_time(now);  // collects the event: sent by on_rs4_event
  }
  if (!acknowledge_requested && counters_.events == events) {  // (already latched: no event)
    ++counters_.error_telegrams;
    send(adapter::error_telegram(rs4, v.error, v.parameter, adapter::kRs4ErrorFunctionCommands),
         now);
  }
}

void Rs232Port::acknowledge(std::uint8_t code, stream::TimePoint now) {
  ++counters_.acks;
  send(adapter::ack_telegram(adapter_.scanner(), code), now);
}

}  // namespace rs4sim::rs4::rs232
