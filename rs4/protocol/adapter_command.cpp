#include "rs4/protocol/adapter_command.h"

namespace rs4sim::rs4::protocol {
namespace {

constexpr std::uint8_t code(AdapterCommandCode c) noexcept { return static_cast<std::uint8_t>(c); }

RejectedCommand wrong_length(std::uint8_t command) noexcept {
  return {CommandErrorKind::kWrongLength, command};
}

WriteCommand parse_get_rs4_data(std::span<const std::uint8_t> payload) {
  // Table 5.2-5: 92 mask mode, exactly three bytes.
  if (payload.size() != 3) return wrong_length(payload[0]);
  const std::uint8_t mask = payload[1];
  const std::uint8_t mode = payload[2];
  // Bits 4..7 of the mask select nothing the manual defines; mode > 1 is "nicht zulässig".
  if ((mask & ~kForwardMaskDefined) != 0 ||
      mode > static_cast<std::uint8_t>(ForwardMode::kPermanent)) {
    return RejectedCommand{CommandErrorKind::kWrongParameter, payload[0]};
  }
  return GetRs4DataCommand{mask, static_cast<ForwardMode>(mode)};
}

WriteCommand parse_proxy_end(std::span<const std::uint8_t> payload) {
  // EXTENSION ([docs/proxy-protocol.md]): 99 outcome error_hi error_lo, exactly four bytes.
  if (payload.size() != 4) return wrong_length(payload[0]);
  const std::uint8_t outcome = payload[1];
  const auto error = static_cast<std::uint16_t>((payload[2] << 8U) | payload[3]);
  const bool succeeded = outcome == static_cast<std::uint8_t>(ProxyOutcome::kSucceeded);
  const bool failed = outcome == static_cast<std::uint8_t>(ProxyOutcome::kFailed);
  if ((succeeded && error != 0) || (failed && !is_proxy_end_error(error)) ||
      (!succeeded && !failed)) {
    return RejectedCommand{CommandErrorKind::kWrongParameter, payload[0]};
  }
  return ProxyEndCommand{succeeded ? ProxyOutcome::kSucceeded : ProxyOutcome::kFailed, error};
}

template <typename Command>
WriteCommand single_byte(std::span<const std::uint8_t> payload) {
  if (payload.size() != 1) return wrong_length(payload[0]);
  return Command{};
}

}  // namespace

std::uint8_t forward_mask_bit(std::uint8_t telegram_code) noexcept {
  switch (telegram_code) {
    case 0x23: return kForwardMeasurement;  // COM_CMD_MESS_16_RT
    case 0x14: return kForwardAlive;        // COM_CMD_ALIVE
    case 0x54: return kForwardWarning;      // COM_CMD_WARNING_OCCURE
    case 0x53: return kForwardError;        // COM_CMD_ERROR_OCCURE
    default: return 0;
  }
}

bool is_proxy_end_error(std::uint16_t error) noexcept {
  // 0x2B01 unknown proxy state, 0x2B09 CRC comparison, 0x2B1x echo CRC, 0x2B2x read repetition
  const unsigned family = error & 0xFFF0U;
  return error == 0 || error == 0x2B01 || error == 0x2B09 || family == 0x2B10U || family == 0x2B20U;
}

Result<WriteCommand> parse_write_command(std::span<const std::uint8_t> payload) {
  if (payload.empty()) return ProtocolError::kEmptyCommand;
  switch (static_cast<AdapterCommandCode>(payload[0])) {
    case AdapterCommandCode::kReset: return single_byte<ResetCommand>(payload);
    case AdapterCommandCode::kGetRs4Data: return parse_get_rs4_data(payload);
    case AdapterCommandCode::kGetVersion: return single_byte<GetVersionCommand>(payload);
    case AdapterCommandCode::kError: return single_byte<GetLastErrorCommand>(payload);
    case AdapterCommandCode::kGetError: return single_byte<GetErrorMemoryCommand>(payload);
    case AdapterCommandCode::kProxyBegin: return single_byte<ProxyBeginCommand>(payload);
    case AdapterCommandCode::kProxyEnd: return parse_proxy_end(payload);
    case AdapterCommandCode::kErrorInTelegram:  // an answer code, not a command
    default: return WriteCommand{Rs4Command{payload}};
  }
}

std::vector<std::uint8_t> encode_command(const ResetCommand&) {
  return {code(AdapterCommandCode::kReset)};
}
std::vector<std::uint8_t> encode_command(const GetRs4DataCommand& command) {
  return {code(AdapterCommandCode::kGetRs4Data), command.mask,
          static_cast<std::uint8_t>(command.mode)};
}
std::vector<std::uint8_t> encode_command(const GetVersionCommand&) {
  return {code(AdapterCommandCode::kGetVersion)};
}
std::vector<std::uint8_t> encode_command(const GetLastErrorCommand&) {
  return {code(AdapterCommandCode::kError)};
}
std::vector<std::uint8_t> encode_command(const GetErrorMemoryCommand&) {
  return {code(AdapterCommandCode::kGetError)};
}

std::vector<std::uint8_t> encode_command(const ProxyBeginCommand&) {
  return {code(AdapterCommandCode::kProxyBegin)};
}
std::vector<std::uint8_t> encode_command(const ProxyEndCommand& command) {
  return {code(AdapterCommandCode::kProxyEnd), static_cast<std::uint8_t>(command.outcome),
          static_cast<std::uint8_t>(command.error >> 8U),
          static_cast<std::uint8_t>(command.error & 0xFFU)};
}

std::vector<std::uint8_t> encode_rejection(const RejectedCommand& rejected) {
  return {code(AdapterCommandCode::kErrorInTelegram), static_cast<std::uint8_t>(rejected.kind),
          rejected.command};
}

Result<RejectedCommand> decode_rejection(std::span<const std::uint8_t> answer) {
  if (answer.empty() || answer[0] != code(AdapterCommandCode::kErrorInTelegram)) {
    return ProtocolError::kBadAnswerCode;
  }
  if (answer.size() != 3) return ProtocolError::kBadAnswerLength;
  if (answer[1] > static_cast<std::uint8_t>(CommandErrorKind::kWrongParameter)) {
    return ProtocolError::kBadAnswerValue;
  }
  return RejectedCommand{static_cast<CommandErrorKind>(answer[1]), answer[2]};
}

}  // namespace rs4sim::rs4::protocol
