#include "rs4/protocol/telegram.h"

#include "codec/reader.h"
#include "codec/writer.h"

namespace rs4sim::rs4::protocol {
namespace {

constexpr std::size_t kErrorReportSize = 6;

std::uint8_t code_byte(TelegramCode code) noexcept { return static_cast<std::uint8_t>(code); }

std::error_code encode_body(const AliveTelegram& t, std::vector<std::uint8_t>& out) {
  return encode_prefix(code_byte(TelegramCode::kAlive), t.prefix, out);
}

std::error_code encode_report(TelegramCode code, const TelegramPrefix& prefix, const ErrorReport& r,
                              std::vector<std::uint8_t>& out) {
  if (auto ec = encode_prefix(code_byte(code), prefix, out)) return ec;
  codec::Appender w(out);
  for (const auto v : {r.number, r.parameter, r.function}) w.u16_be(v);
  return {};
}

std::error_code encode_body(const ErrorTelegram& t, std::vector<std::uint8_t>& out) {
  return encode_report(TelegramCode::kErrorOccure, t.prefix, t.report, out);
}
std::error_code encode_body(const WarningTelegram& t, std::vector<std::uint8_t>& out) {
  return encode_report(TelegramCode::kWarningOccure, t.prefix, t.report, out);
}
std::error_code encode_body(const MeasurementTelegram& t, std::vector<std::uint8_t>& out) {
  if (auto ec = encode_prefix(code_byte(TelegramCode::kMess16Rt), t.prefix, out)) return ec;
  return encode_measurement_data(t, out);
}

std::error_code exact_size(std::span<const std::uint8_t> data, std::size_t size) noexcept {
  if (data.size() < size) return ProtocolError::kTruncated;
  if (data.size() > size) return ProtocolError::kTrailingBytes;
  return {};
}

template <typename Report>
Result<Rs4Telegram> decode_report(const TelegramPrefix& prefix,
                                  std::span<const std::uint8_t> data) {
  if (auto ec = exact_size(data, kErrorReportSize)) return ec;
  codec::Reader r(data);
  return Rs4Telegram{Report{prefix, ErrorReport{r.u16_be(), r.u16_be(), r.u16_be()}}};
}

}  // namespace

TelegramCode telegram_code(const Rs4Telegram& telegram) noexcept {
  constexpr TelegramCode kCodes[] = {TelegramCode::kAlive, TelegramCode::kErrorOccure,
                                     TelegramCode::kWarningOccure, TelegramCode::kMess16Rt};
  return kCodes[telegram.index()];
}

Result<std::vector<std::uint8_t>> encode_telegram(const Rs4Telegram& telegram) {
  std::vector<std::uint8_t> out;
  const auto ec = std::visit([&out](const auto& t) { return encode_body(t, out); }, telegram);
  if (ec) return ec;
  return out;
}

bool is_known_code(std::uint8_t code) noexcept {
  switch (static_cast<TelegramCode>(code)) {
    case TelegramCode::kAlive:
    case TelegramCode::kMess16Rt:
    case TelegramCode::kErrorOccure:
    case TelegramCode::kWarningOccure: return true;
  }
  return false;
}

Result<Rs4Telegram> decode_telegram(std::span<const std::uint8_t> body) {
  if (body.empty()) return ProtocolError::kTruncated;
  if (!is_known_code(body[0])) return ProtocolError::kUnknownTelegram;
  auto decoded = decode_prefix(body);
  if (!decoded) return decoded.error();
  const auto& d = decoded.value();
  const auto data = body.subspan(d.size);
  switch (static_cast<TelegramCode>(d.code)) {
    case TelegramCode::kAlive:
      if (auto ec = exact_size(data, 0)) return ec;
      return Rs4Telegram{AliveTelegram{d.prefix}};
    case TelegramCode::kErrorOccure: return decode_report<ErrorTelegram>(d.prefix, data);
    case TelegramCode::kWarningOccure: return decode_report<WarningTelegram>(d.prefix, data);
    case TelegramCode::kMess16Rt: {
      MeasurementTelegram t;
      t.prefix = d.prefix;
      if (auto ec = decode_measurement_data(data, t)) return ec;
      return Rs4Telegram{std::move(t)};
    }
  }
  return ProtocolError::kUnknownTelegram;
}

}  // namespace rs4sim::rs4::protocol
