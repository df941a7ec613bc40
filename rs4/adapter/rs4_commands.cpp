#include "rs4/adapter/rs4_commands.h"

#include "rs4/protocol/measurement.h"
#include "rs4/protocol/option_bytes.h"
#include "rs4/protocol/parameter_transfer.h"
#include "rs4/protocol/telegram.h"
#include "rs4/scanner/measurement.h"
#include "rs4/scanner/parameter_codec.h"

#include "codec/reader.h"
#include "codec/writer.h"

#include <algorithm>

namespace rs4sim::rs4::adapter {

protocol::TelegramPrefix rs4_prefix(const scanner::Scanner& rs4) {
  const auto st = rs4.status();
  protocol::TelegramPrefix p;
  auto& o = p.options;
  o.state = static_cast<protocol::Option1State>(st.state);  // same values ([RS4 manual §5.2.3]
                                                            // option 1)
  o.flags.protective_field_occupied = st.protective_violated;
  o.flags.warning_field_occupied = st.warning_violated;
  o.flags.warning = st.contamination_warning;
  o.flags.fault = st.fault;
  o.flags.restart_interlock = st.restart_interlock;
  o.flags.second_protective_field_occupied = st.second_protective_violated;
  o.flags.second_warning_field_occupied = st.second_warning_violated;
  o.first_field_pair = st.first_pair;
  o.second_field_pair = st.second_pair;
  return p;
}

namespace {

std::vector<std::uint8_t> report_telegram(protocol::TelegramCode code, const scanner::Scanner& rs4,
                                          const protocol::ErrorReport& report) {
  std::vector<std::uint8_t> out;
  if (code == protocol::TelegramCode::kErrorOccure) {
    auto r = protocol::encode_telegram(protocol::ErrorTelegram{rs4_prefix(rs4), report});
    if (r) out = std::move(r.value());
  } else {
    auto r = protocol::encode_telegram(protocol::WarningTelegram{rs4_prefix(rs4), report});
    if (r) out = std::move(r.value());
  }
  return out;
}

bool scanning(const scanner::Scanner& rs4) {
  const auto s = rs4.status().state;
  return (s == scanner::ScannerState::kMeasuring || s == scanner::ScannerState::kError) &&
         rs4.status().scan_counter != 0;
}

}  // namespace

std::vector<std::uint8_t> error_telegram(const scanner::Scanner& rs4, std::uint16_t number,
                                         std::uint16_t parameter, std::uint16_t function) {
  return report_telegram(protocol::TelegramCode::kErrorOccure, rs4, {number, parameter, function});
}

std::vector<std::uint8_t> event_telegram(const scanner::Scanner& rs4, const scanner::Rs4Event& e) {
  const auto code = e.kind == scanner::Rs4Event::Kind::kError
                        ? protocol::TelegramCode::kErrorOccure
                        : protocol::TelegramCode::kWarningOccure;
  return report_telegram(code, rs4, {e.number, e.parameter, e.function});
}

std::vector<std::uint8_t> alive_telegram(const scanner::Scanner& rs4) {
  auto r = protocol::encode_telegram(protocol::AliveTelegram{rs4_prefix(rs4)});
  return r ? std::move(r.value()) : std::vector<std::uint8_t>{};
}

std::vector<std::uint8_t> measurement_telegram(const scanner::Scanner& rs4) {
  const auto& window = rs4.parameters().measurement;
  const auto flagged = scanner::measurement_contour(rs4.last_scan(), window);
  std::vector<std::uint8_t> out;
  if (protocol::encode_prefix(static_cast<std::uint8_t>(protocol::TelegramCode::kMess16Rt),
                              rs4_prefix(rs4), out)) {
    return {};
  }
  if (protocol::encode_measurement_data(rs4.last_scan().scan_number, window.resolution,
                                        window.start, window.stop, flagged, out)) {
    return {};
  }
  return out;
}

std::optional<std::uint16_t> baud_code(std::uint32_t baud) noexcept {
  for (std::size_t i = 0; i < kBaudRates.size(); ++i) {
    if (kBaudRates[i] == baud) return static_cast<std::uint16_t>(i);
  }
  return std::nullopt;
}

std::optional<std::uint32_t> baud_of_code(std::uint16_t code) noexcept {
  if (code >= kBaudRates.size()) return std::nullopt;
  return kBaudRates[code];
}

bool protected_command(std::uint8_t code) noexcept {
  return code == kRs4CheckPassword || code == kRs4MeasurementWindow ||
         (protocol::is_transfer_code(code) &&
          code >= static_cast<std::uint8_t>(protocol::TransferCode::kDownloadBegin));
}

namespace {
bool empty_password(const scanner::Password& p) noexcept {
  return std::all_of(p.begin(), p.end(), [](std::uint8_t b) { return b == 0xFF; });
}
}  // namespace

bool password_accepted(const scanner::ParameterSet& set, const protocol::TelegramPrefix& prefix,
                       const std::array<std::uint8_t, 8>& factory) noexcept {
  if (!prefix.options.password) return false;
  const auto& user = set.passwords;
  if (std::all_of(user.begin(), user.end(), empty_password)) return prefix.password == factory;
  return std::any_of(user.begin(), user.end(), [&](const scanner::Password& p) {
    return !empty_password(p) && p == prefix.password;
  });
}

bool setting_command(std::uint8_t code) noexcept {
  return code == kRs4CheckPassword || code == kRs4SetBaud || code == kRs4MeasurementWindow ||
         code == kRs4StreamControl;
}

namespace {
CommandVerdict set_window(scanner::Scanner& rs4, std::span<const std::uint8_t> data,
                          scanner::TimePoint now) {
  codec::Reader r(data);
  scanner::MeasurementOutput m;
  m.resolution = r.u8();
  m.start = r.u16_be();
  m.stop = r.u16_be();
  if (!r.ok() || !r.at_end() || !protocol::measurement_value_count(m.start, m.stop, m.resolution)) {
    return {kRs4ErrorBadData, kRs4MeasurementWindow};
  }
  auto set = rs4.parameters();
  set.measurement = m;
  if (scanner::validate(set)) return {kRs4ErrorBadData, kRs4MeasurementWindow};
  if (!rs4.enter_configuration(now)) {
    return {kRs4ErrorNotOperational, static_cast<std::uint16_t>(rs4.status().state)};
  }
  const bool applied = static_cast<bool>(rs4.set_parameters(set, now));
  (void)rs4.leave_configuration(now);
  return applied ? CommandVerdict{} : CommandVerdict{kRs4ErrorBadData, kRs4MeasurementWindow};
}
}  // namespace

CommandVerdict execute_setting(scanner::Scanner& rs4, std::uint8_t code,
                               std::span<const std::uint8_t> data, scanner::TimePoint now) {
  switch (code) {
    case kRs4CheckPassword:
      return data.empty() ? CommandVerdict{} : CommandVerdict{kRs4ErrorBadData, code};
    case kRs4SetBaud: {
      codec::Reader r(data);
      const std::uint16_t rate = r.u16_be();
      if (!r.ok() || !r.at_end() || !baud_of_code(rate)) return {kRs4ErrorBadData, code};
      return {};
    }
    case kRs4StreamControl:
      return data.size() == 1 && data[0] <= 1 ? CommandVerdict{}
                                              : CommandVerdict{kRs4ErrorBadData, code};
    case kRs4MeasurementWindow: return set_window(rs4, data, now);
    default: break;
  }
  return {kRs4ErrorUnknownCommand, code};
}

std::vector<std::uint8_t> ack_telegram(const scanner::Scanner& rs4, std::uint8_t code) {
  std::vector<std::uint8_t> out;
  (void)protocol::encode_prefix(kRs4Ack, rs4_prefix(rs4), out);  // options from the model
  out.push_back(code);
  return out;
}

std::vector<std::uint8_t> nak_telegram(const scanner::Scanner& rs4, std::uint8_t code,
                                       std::uint16_t error) {
  std::vector<std::uint8_t> out;
  (void)protocol::encode_prefix(kRs4Nak, rs4_prefix(rs4), out);
  codec::Appender w(out);
  w.u8(code);
  w.u16_be(error);
  return out;
}

std::vector<std::uint8_t> answer_rs4_command(const scanner::Scanner& rs4,
                                             std::span<const std::uint8_t> command) {
  const auto prefix = protocol::decode_prefix(command);
  const std::uint8_t code = command.empty() ? 0 : command[0];
  const bool known = code == kRs4RequestOneScan ||
                     code == static_cast<std::uint8_t>(protocol::TelegramCode::kAlive);
  // Options that do not decode, or data after a command that takes none: bad data, on both paths
  // (docs/decisions.md#rs4-one-command-set).
  if (!prefix || (known && prefix.value().size != command.size())) {
    return error_telegram(rs4, kRs4ErrorBadData, code, kRs4ErrorFunctionCommands);
  }
  if (code == kRs4RequestOneScan) {
    if (!scanning(rs4)) {
      return error_telegram(rs4, kRs4ErrorNoScan, static_cast<std::uint16_t>(rs4.status().state),
                            kRs4ErrorFunctionCommands);
    }
    auto t = measurement_telegram(rs4);
    if (!t.empty()) return t;
  } else if (known) {
    return alive_telegram(rs4);
  }
  // [RS4 manual §5.2.2]: a command the RS4 does not know is answered with an error telegram.
  return error_telegram(rs4, kRs4ErrorUnknownCommand, code, kRs4ErrorFunctionCommands);
}

}  // namespace rs4sim::rs4::adapter
