// Adapter: acyclic data exchange ([RS4 manual §5.2]): slot 0,
// index 2/3, block protocol with the flow-control byte, adapter commands and RS4 commands.
#include "rs4/adapter/adapter.h"
#include "rs4/adapter/rs4_commands.h"
#include "rs4/protocol/adapter_command.h"
#include "rs4/protocol/parameter_transfer.h"
#include "rs4/protocol/telegram.h"

#include <algorithm>
#include <variant>

namespace rs4sim::rs4::adapter {

namespace {
using dp::pdu::ErrorCode1;
using dp::slave::AcyclicChannel;
using dp::slave::AcyclicError;
using dp::slave::AcyclicResult;
// DPV1 negative responses ([IEC 61158-6-3 MSAC_C1]), Error_Decode 0x80 = DPV1.
constexpr AcyclicError kInvalidIndex{0x80, ErrorCode1::kInvalidIndex, 0x00};
constexpr AcyclicError kWriteLengthError{0x80, ErrorCode1::kWriteLengthError, 0x00};
constexpr AcyclicError kInvalidSlot{0x80, ErrorCode1::kInvalidSlot, 0x00};
constexpr AcyclicError kInvalidParameter{0x80, ErrorCode1::kInvalidParameter, 0x00};
constexpr AcyclicError kNotSupported{0x80, ErrorCode1::kFeatureNotSupported, 0x00};
}  // namespace

Adapter::Channel& Adapter::channel(AcyclicChannel which) noexcept {
  return which == AcyclicChannel::kC1 ? c1_ : c2_;
}
const Adapter::Channel& Adapter::channel(AcyclicChannel which) const noexcept {
  return which == AcyclicChannel::kC1 ? c1_ : c2_;
}
std::size_t Adapter::pending_answers(AcyclicChannel which) const noexcept {
  const auto& ch = channel(which);
  return ch.processing.size() + ch.answers.size() + (ch.reading.done() ? 0 : 1);
}

// Table 5.2-2 bits 6..4. DECISION: 011 is shown to every master while a proxy sync runs
// (the proxy's own requests on C1 are processed normally).
protocol::FlowState Adapter::flow_state(AcyclicChannel which) const noexcept {
  if (!powered_ || init_end_ || link_down_until_) return protocol::FlowState::kNoCommunicationPath;
  if (pc_.switched_through()) return protocol::FlowState::kPcAdapterAttached;
  if (proxy_.running()) return protocol::FlowState::kProxyBusy;
  if (which == AcyclicChannel::kC2 && !connected_) return protocol::FlowState::kNoConnection;
  return protocol::FlowState::kNormal;
}

// Bit 0: the adapter takes the first/next WRITE block: it is running and a read buffer
// is free for the result.
bool Adapter::ready_for_write(AcyclicChannel which) const noexcept {
  const auto state = flow_state(which);
  if (state == protocol::FlowState::kNoCommunicationPath ||
      state == protocol::FlowState::kPcAdapterAttached) {
    return false;
  }
  return pending_answers(which) < config_.read_buffers;
}

std::uint8_t Adapter::flow_byte(AcyclicChannel which, bool payload) const noexcept {
  return protocol::encode_flow_control({ready_for_write(which), payload, flow_state(which)});
}

dp::slave::AcyclicResult Adapter::on_acyclic(const dp::slave::AcyclicRequest& req, TimePoint now) {
  if (!powered_) return AcyclicResult::fail(kNotSupported);
  collect_rs4(now);
  finish_processing(now);
  // [docs/proxy-protocol.md] step 6: any class 2 READ/WRITE during a sync is a user command.
  if (req.channel == AcyclicChannel::kC2) abort_on_user_command({}, req.channel, now);
  if (req.service == dp::slave::AcyclicService::kDataTransport) {
    ++counters_.dpv1_rejected;
    return AcyclicResult::fail(kNotSupported);
  }
  // [RS4 manual §5.2]: slot 0 only, index 2 or 3 (treated identically).
  if (req.slot != 0 || (req.index != 2 && req.index != 3)) {
    ++counters_.dpv1_rejected;
    return AcyclicResult::fail(req.slot != 0 ? kInvalidSlot : kInvalidIndex);
  }
  auto& ch = channel(req.channel);
  return req.service == dp::slave::AcyclicService::kWrite ? on_write(req, ch, now)
                                                          : on_read(req, ch, now);
}

dp::slave::AcyclicResult Adapter::on_write(const dp::slave::AcyclicRequest& req, Channel& ch,
                                           TimePoint now) {
  ++counters_.writes;
  if (req.channel == AcyclicChannel::kC2 && req.first_write_after_initiate && control_) {
    // [RS4 manual §5.3.1]: update alarm to the class 1 master, 04 06 00 spec (ack required).
    const dp::slave::AlarmRequest alarm{protocol::kAlarmTypeUpdate, 0, 0, true, {}};
    if (control_->submit_alarm(alarm))
      ++counters_.alarms_refused;
    else
      ++counters_.alarms_submitted;
  }
  // [RS4 manual §5.2]: records of 5..240 bytes.
  if (req.data.size() < protocol::kMinWriteRecordSize ||
      req.data.size() > protocol::kMaxRecordSize) {
    ++counters_.dpv1_rejected;
    return AcyclicResult::fail(kWriteLengthError);
  }
  if (flow_state(req.channel) == protocol::FlowState::kPcAdapterAttached) {
    ++counters_.writes_ignored;  // [RS4 manual §5.2.1] state 010: WRITEs are ignored without error
    return AcyclicResult::ok();
  }
  if (!ready_for_write(req.channel)) {
    // Bit 0 = 0: not processed; error buffer + diagnosis alarm (table 5.2-2).
    const bool full = pending_answers(req.channel) >= config_.read_buffers &&
                      flow_state(req.channel) != protocol::FlowState::kNoCommunicationPath;
    adapter_error(full ? protocol::AdapterError::kReadBuffersFull
                       : protocol::AdapterError::kTelegramNotProcessed,
                  now);
    return AcyclicResult::ok();
  }
  const auto progress = ch.assembler.push(req.data);
  if (!progress) {
    const auto ec = progress.error();
    if (ec == protocol::AdapterError::kTelegramTooLong) {
      adapter_error(protocol::AdapterError::kTelegramTooLong, now);
    } else if (ec == protocol::AdapterError::kUnexpectedBlockNumber) {
      adapter_error(protocol::AdapterError::kUnexpectedBlockNumber, now);
    } else {  // a block whose header does not describe it: cannot be processed
      adapter_error(protocol::AdapterError::kTelegramNotProcessed, now);
    }
    return AcyclicResult::ok();
  }
  if (progress.value().complete) {
    const std::vector<std::uint8_t> command(ch.assembler.command().begin(),
                                            ch.assembler.command().end());
    execute(command, req.channel, ch, now);
  }
  return AcyclicResult::ok();
}

dp::slave::AcyclicResult Adapter::on_read(const dp::slave::AcyclicRequest& req, Channel& ch,
                                          TimePoint now) {
  ++counters_.reads;
  if (req.length < protocol::kMinWriteRecordSize) {
    ++counters_.dpv1_rejected;
    return AcyclicResult::fail(kInvalidParameter);  // no room for a block
  }
  const std::size_t block_size = std::min<std::size_t>(req.length, protocol::kMaxRecordSize);
  if (flow_state(req.channel) != protocol::FlowState::kPcAdapterAttached && ch.reading.done()) {
    if (!ch.answers.empty()) {
      ch.reading = protocol::BlockSplitter(std::move(ch.answers.front()), block_size);
      ch.answers.pop_front();
    } else if (req.channel == AcyclicChannel::kC1) {
      if (auto t = take_forwarded())
        ch.reading = protocol::BlockSplitter(std::move(*t), block_size);
    }
  }
  std::vector<std::uint8_t> block;
  if (flow_state(req.channel) != protocol::FlowState::kPcAdapterAttached && !ch.reading.done()) {
    const bool last = ch.reading.remaining_blocks() == 1;
    // The ready bit as it will be once this block is fetched (the buffer frees up).
    const bool ready = ready_for_write(req.channel) ||
                       (last && pending_answers(req.channel) <= config_.read_buffers &&
                        flow_state(req.channel) != protocol::FlowState::kNoCommunicationPath);
    block = ch.reading.next({ready, false, flow_state(req.channel)});
  } else {  // nothing to read: the header alone (table 5.2-1)
    (void)protocol::encode_block(flow_byte(req.channel, false), protocol::kLastBlockNumber, {},
                                 block);
  }
  if (pc_.pending()) switch_through_after_sync(now);
  return AcyclicResult::ok(block);
}

// Whether a class 2 master may use a command: every RS4 command, and of the adapter's commands
// the queries (0x84, 0x90, 0x91), which control nothing. [RS4 manual §5.2.1]: class 2 may use
// "alle RS4-Kommandos …, nicht aber die speziellen Kommandos für den PROFIsafe-Adapter zur
// Steuerung der automatischen Konfiguration" [docs/decisions.md#rs4-class2-adapter-commands].
namespace {
bool class2_may_use(const protocol::WriteCommand& cmd) noexcept {
  return std::holds_alternative<protocol::Rs4Command>(cmd) ||
         std::holds_alternative<protocol::GetVersionCommand>(cmd) ||
         std::holds_alternative<protocol::GetLastErrorCommand>(cmd) ||
         std::holds_alternative<protocol::GetErrorMemoryCommand>(cmd) ||
         std::holds_alternative<protocol::RejectedCommand>(cmd);
}
}  // namespace

// A complete command. [RS4 manual §5.2.2] "Bei jedem empfangenen Klasse 1- oder Klasse
// 2-Telegramm wird anhand des ersten Bytes ermittelt, ob es für den PROFIsafe-Adapter bestimmt
// ist oder für den RS4": on both channels an adapter code is the adapter's, never forwarded to
// the RS4. DECISION: a class 2 master's controlling adapter command (0x92, 0x94, 0x98, 0x99) is
// refused with 93 01 code (table 5.2-3, "falscher Parameter") and has no effect
// [docs/decisions.md#rs4-class2-adapter-commands].
void Adapter::execute(std::span<const std::uint8_t> command, AcyclicChannel which, Channel& ch,
                      TimePoint now) {
  abort_on_user_command(command, which, now);
  const auto parsed = protocol::parse_write_command(command);
  if (!parsed) {
    adapter_error(protocol::AdapterError::kTelegramNotProcessed, now);
    return;
  }
  if (which == AcyclicChannel::kC2 && !class2_may_use(parsed.value())) {
    execute_adapter_command(
        protocol::RejectedCommand{protocol::CommandErrorKind::kWrongParameter, command[0]}, ch,
        now);
    return;
  }
  execute_adapter_command(parsed.value(), ch, now);
}

void Adapter::execute_adapter_command(const protocol::WriteCommand& cmd, Channel& ch,
                                      TimePoint now) {
  if (const auto* rs4 = std::get_if<protocol::Rs4Command>(&cmd)) {
    ++counters_.rs4_commands;
    submit_rs4_command(rs4->bytes, ch, now);
    return;
  }
  ++counters_.adapter_commands;
  if (std::holds_alternative<protocol::ResetCommand>(cmd)) {
    // PROFI_CMD_RESET: the adapter restarts like power-on, the PROFIBUS link is down for
    // ≈2 s (the owner drops it), the RS4 is not affected, the error memory is kept.
    ++counters_.resets;
    start_adapter(now, /*keep_errors=*/true);
    link_down_until_ = now + config_.reset_link_down;
    return;  // `ch` was cleared: no answer
  }
  if (const auto* fwd = std::get_if<protocol::GetRs4DataCommand>(&cmd)) {
    forwarding_ = Forwarding{};
    forwarding_.mask = fwd->mask;
    forwarding_.permanent = fwd->mode == protocol::ForwardMode::kPermanent;
    if (fwd->mask == 0) event_buffer_.clear();  // mask 0: stop all forwarding
    capture_forwarding();
  } else if (std::holds_alternative<protocol::GetVersionCommand>(cmd)) {
    ch.answers.push_back(protocol::encode_version_answer(config_.version));
  } else if (std::holds_alternative<protocol::GetLastErrorCommand>(cmd)) {
    ch.answers.push_back(protocol::encode_last_error_answer(errors_.last_error()));
  } else if (std::holds_alternative<protocol::GetErrorMemoryCommand>(cmd)) {
    ch.answers.push_back(protocol::encode_error_memory_answer(errors_.memory()));
  } else if (std::holds_alternative<protocol::ProxyBeginCommand>(cmd)) {
    proxy_begin(ch, now);
  } else if (const auto* end = std::get_if<protocol::ProxyEndCommand>(&cmd)) {
    proxy_end(*end, ch, now);
  } else if (const auto* bad = std::get_if<protocol::RejectedCommand>(&cmd)) {
    ++counters_.rejected_commands;
    ch.answers.push_back(protocol::encode_rejection(*bad));  // 93 kind command
  }
}

// The transfer commands 0x60..0x65 go to the proxy session, every other one to the RS4 model.
// The RS4 works on a command for `rs4_command_time` ("bis zu 2 Minuten", [RS4 manual §5.2.1]);
// meanwhile a READ finds no answer and the master polls. Commands are processed in order.
void Adapter::submit_rs4_command(std::span<const std::uint8_t> command, Channel& ch,
                                 TimePoint now) {
  if (config_.rs4_command_time <= milliseconds::zero()) {
    ch.answers.push_back(execute_rs4_command(command, now));
    return;
  }
  const TimePoint after = ch.processing.empty() ? now : ch.processing.back().due;
  ch.processing.push_back({after + config_.rs4_command_time,
                           std::vector<std::uint8_t>(command.begin(), command.end())});
}

void Adapter::finish_processing(TimePoint now) {
  bool executed = false;
  for (auto* ch : {&c1_, &c2_}) {
    while (!ch->processing.empty() && ch->processing.front().due <= now) {
      const auto command = std::move(ch->processing.front().command);
      ch->processing.pop_front();
      ch->answers.push_back(execute_rs4_command(command, now));
      executed = true;
    }
  }
  if (executed) refresh_input(now);  // an executed command may have changed the RS4
}

// [RS4 manual §5.2.1] "Alle Kommandos werden transparent von und zur RS232 des RS4 übertragen":
// the RS4 behind the tunnel answers the command set of its RS232 (rs4_commands.h) with the
// same password rule. DECISION: the proxy's transfer inside a sync it was asked for needs no
// password (the Proxy-FB holds none: "Die Benutzerkennwörter werden durch den Proxy-FB beim
// Parameter-Download nicht überschrieben" [RS4 manual §7.2.4]); a setting command, which has
// no answer of its own, is acknowledged with 0x16 so that the master's READ finds one
// [docs/decisions.md#rs4-one-command-set].
std::vector<std::uint8_t> Adapter::execute_rs4_command(std::span<const std::uint8_t> command,
                                                       TimePoint now) {
  const std::uint8_t code = command.empty() ? 0 : command[0];
  const auto prefix = protocol::decode_prefix(command);
  const bool proxy_transfer = protocol::is_transfer_code(code) && proxy_.running();
  std::vector<std::uint8_t> answer;
  if (!prefix) {
    // Option bytes that do not decode: bad data, as on the RS232 (rs232_interpreter.cpp), before
    // any other rule [docs/decisions.md#rs4-one-command-set].
    answer = error_telegram(scanner_, kRs4ErrorBadData, code, kRs4ErrorFunctionCommands);
  } else if (protected_command(code) && !proxy_transfer &&
             !password_accepted(scanner_.parameters(), prefix.value().prefix,
                                config_.factory_password)) {
    answer =
        prefix.value().prefix.options.acknowledge
            ? nak_telegram(scanner_, code, kRs4ErrorWrongPassword)
            : error_telegram(scanner_, kRs4ErrorWrongPassword, code, kRs4ErrorFunctionCommands);
  } else if (protocol::is_transfer_code(code)) {
    return transfer(command, now, /*authorised=*/!proxy_transfer);
  } else if (setting_command(code)) {
    auto setting = execute_setting_command(command, prefix.value(), now);
    if (!setting) return ack_telegram(scanner_, code);
    answer = std::move(*setting);
  } else {
    answer = answer_rs4_command(scanner_, command);
  }
  report_rs4_refusal(answer, command, now);
  return answer;
}

// A setting command (0x10, 0x19, 0x20, 0x22): nullopt when executed, else the refusal.
std::optional<std::vector<std::uint8_t>> Adapter::execute_setting_command(
    std::span<const std::uint8_t> command, const protocol::DecodedPrefix& prefix, TimePoint now) {
  const std::uint8_t code = command[0];
  const auto before = scanner_.change_counter();
  const auto v = execute_setting(scanner_, code, command.subspan(prefix.size), now);
  // A new window is a change of the set like a user's download: the proxy is asked to take it
  // (an upload), as after the removal of the PC adapter [RS4 manual §7.2.2], with its own
  // reason 4 [docs/decisions.md#rs4-user-parametrisation-reason].
  if (scanner_.change_counter() != before && gate_.rs4_up() && !pc_.attached() &&
      !proxy_.running()) {
    request_sync(protocol::SyncReason::kUserParametrisation);
  }
  collect_rs4(now);
  if (v.ok()) return std::nullopt;
  return prefix.prefix.options.acknowledge
             ? nak_telegram(scanner_, code, v.error)
             : error_telegram(scanner_, v.error, v.parameter, kRs4ErrorFunctionCommands);
}

// [RS4 manual §5.2.3.2, §5.3.2]: the 0x53 the RS4 answers with is an error of the RS4 like those
// it reports by itself: error memory and a diagnosis alarm. A command the RS4 does not know
// puts it into its error state, OSSD off ([RS4 manual §5.2.2] "RS4 geht in Fehlerzustand"): the
// scanner raises that error itself; one it knows but cannot execute now leaves it protecting
// [docs/decisions.md#rs4-rejected-command].
void Adapter::report_rs4_refusal(std::span<const std::uint8_t> answer,
                                 std::span<const std::uint8_t> command, TimePoint now) {
  const auto t = protocol::decode_telegram(answer);
  if (!t) return;
  const auto* e = std::get_if<protocol::ErrorTelegram>(&t.value());
  if (e == nullptr) return;
  if (e->report.number == kRs4ErrorUnknownCommand && !command.empty()) {
    scanner_.unknown_command(command[0], now);
    collect_rs4(now);
  } else {
    report_error(e->report.number, 0, now);
  }
}

}  // namespace rs4sim::rs4::adapter
