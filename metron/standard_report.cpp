#include "metron/standard_report.h"

#include <chrono>

namespace rs4sim::metron {
namespace {

constexpr char kHexDigits[] = "0123456789ABCDEF";

void put_value(std::vector<std::uint8_t>& out, std::uint8_t v, Format f) {
  switch (f) {
    case Format::kBinary: out.push_back(v); return;
    case Format::kHex:
      out.push_back(static_cast<std::uint8_t>(kHexDigits[v >> 4]));
      out.push_back(static_cast<std::uint8_t>(kHexDigits[v & 0x0F]));
      return;
    case Format::kDecimal:
      out.push_back(static_cast<std::uint8_t>('0' + v / 100));
      out.push_back(static_cast<std::uint8_t>('0' + (v / 10) % 10));
      out.push_back(static_cast<std::uint8_t>('0' + v % 10));
      return;
  }
}

std::size_t digits(Format f) { return f == Format::kBinary ? 1 : (f == Format::kHex ? 2 : 3); }

}  // namespace

std::vector<std::uint8_t> encode_report(std::span<const std::uint8_t> values, const ReportFormat& f,
                                        const WireTable& table, ChecksumReading reading) {
  // The data characters first: the checksum may sum them (ReportLayout).
  std::vector<std::uint8_t> data;
  data.reserve(report_length(values.size(), f));
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0 && f.separator) data.push_back(table.separator);
    put_value(data, values[i], f.format);
  }
  std::vector<std::uint8_t> out;
  out.reserve(report_length(values.size(), f));
  for (const auto part : table.report.order) {
    switch (part) {
      case ReportField::kStart: out.push_back(table.report_start); break;
      case ReportField::kData: out.insert(out.end(), data.begin(), data.end()); break;
      case ReportField::kChecksum:
        if (f.checksum)
          out.push_back(checksum(table.report.checksum_over_characters ? data : values, reading));
        break;
      case ReportField::kEnd: out.push_back(table.report_end); break;
    }
  }
  return out;
}

std::optional<std::size_t> report_checksum_offset(const WireTable& table, const ReportFormat& f,
                                                  std::size_t frame_size) {
  if (!f.checksum || frame_size < 3) return std::nullopt;
  std::size_t at = 0;
  for (const auto part : table.report.order) {
    if (part == ReportField::kChecksum) return at;
    at += part == ReportField::kData ? frame_size - 3 : 1;
  }
  return std::nullopt;
}

std::size_t report_length(std::size_t n, const ReportFormat& f) {
  const std::size_t d = digits(f.format);
  const std::size_t base = f.separator ? (d + 1) * n + 1 : d * n + 2;
  return base + (f.checksum ? 1 : 0);
}

stream::Duration send_time(std::size_t length, const stream::LineSettings& line) {
  using namespace std::chrono;
  const auto bits = static_cast<std::uint64_t>(length) * bits_per_character(line);
  // bits / baud seconds, rounded up to the nanosecond, plus the fixed 1 ms pause.
  const auto ns = (bits * 1'000'000'000ULL + line.baud - 1) / line.baud;
  return duration_cast<stream::Duration>(nanoseconds(ns) + milliseconds(1));
}

stream::Duration reply_delay(std::size_t n_byte, stream::Duration t_response) {
  using namespace std::chrono;
  // 0.05208 ms is the manual's rounding of one bit at 19200 baud (52.083 us): the exact
  // bit time is used, n_byte * 11 / 19200 s.
  const auto bits = static_cast<std::uint64_t>(n_byte) * 11U;
  const auto ns = (bits * 1'000'000'000ULL + 19199U) / 19200U;
  return duration_cast<stream::Duration>(nanoseconds(ns)) + t_response / 2;
}

}  // namespace rs4sim::metron
