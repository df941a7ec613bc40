#include "rs4/protocol/measurement.h"

namespace rs4sim::rs4::protocol {
namespace {

void put16(std::vector<std::uint8_t>& out, std::uint16_t v) {
  out.push_back(static_cast<std::uint8_t>(v >> 8));
  out.push_back(static_cast<std::uint8_t>(v & 0xFFU));
}

std::uint16_t get16(std::span<const std::uint8_t> in, std::size_t at) noexcept {
  return static_cast<std::uint16_t>((in[at] << 8) | in[at + 1]);
}

// Scan number, resolution, start, stop (table 5.2-14 bytes 9..21).
void put_header(std::uint32_t scan, std::uint8_t resolution, std::uint16_t start,
                std::uint16_t stop, std::vector<std::uint8_t>& out) {
  for (int shift = 24; shift >= 0; shift -= 8) {
    out.push_back(static_cast<std::uint8_t>((scan >> shift) & 0xFFU));
    out.push_back(kScanNumberFiller);  // keeps small numbers from making runs of zeros
  }
  out.push_back(resolution);
  put16(out, start);
  put16(out, stop);
}

}  // namespace

Result<std::size_t> measurement_value_count(std::uint16_t start, std::uint16_t stop,
                                            std::uint8_t resolution) noexcept {
  if (resolution == 0) return ProtocolError::kBadResolution;
  if (start > kMaxSegment || stop > kMaxSegment) return ProtocolError::kSegmentOutOfRange;
  if (start > stop) return ProtocolError::kStartAfterStop;
  const std::size_t span = static_cast<std::size_t>(stop - start);
  // start, start+res, … ≤ stop, plus stop itself when the steps do not land on it.
  return span / resolution + 1 + (span % resolution != 0 ? 1 : 0);
}

std::error_code encode_measurement_data(const MeasurementTelegram& t,
                                        std::vector<std::uint8_t>& out) {
  auto count = measurement_value_count(t.start, t.stop, t.resolution);
  if (!count) return count.error();
  if (count.value() != t.values.size()) return ProtocolError::kValueCountMismatch;
  out.reserve(out.size() + kMeasurementHeaderSize + 2 * t.values.size());
  put_header(t.scan_number, t.resolution, t.start, t.stop, out);
  for (const auto value : t.values) put16(out, value);
  return {};
}

std::error_code encode_measurement_data(std::uint32_t scan_number, std::uint8_t resolution,
                                        std::uint16_t start, std::uint16_t stop,
                                        std::span<const std::uint16_t, kContourSegments> contour,
                                        std::vector<std::uint8_t>& out) {
  auto count = measurement_value_count(start, stop, resolution);
  if (!count) return count.error();
  out.reserve(out.size() + kMeasurementHeaderSize + 2 * count.value());
  put_header(scan_number, resolution, start, stop, out);
  std::size_t segment = start;
  for (; segment < stop; segment += resolution) put16(out, contour[segment]);
  put16(out, contour[stop]);  // the stop segment is always output (§6.1)
  return {};
}

std::error_code decode_measurement_data(std::span<const std::uint8_t> data,
                                        MeasurementTelegram& t) {
  if (data.size() < kMeasurementHeaderSize) return ProtocolError::kTruncated;
  std::uint32_t scan = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    if (data[2 * i + 1] != kScanNumberFiller) return ProtocolError::kBadScanNumberFiller;
    scan = (scan << 8) | data[2 * i];
  }
  t.scan_number = scan;
  t.resolution = data[8];
  t.start = get16(data, 9);
  t.stop = get16(data, 11);
  auto count = measurement_value_count(t.start, t.stop, t.resolution);
  if (!count) return count.error();
  const std::size_t values_size = data.size() - kMeasurementHeaderSize;
  if (values_size < 2 * count.value()) return ProtocolError::kTruncated;
  if (values_size > 2 * count.value()) return ProtocolError::kTrailingBytes;
  t.values.resize(count.value());
  for (std::size_t i = 0; i < count.value(); ++i) {
    t.values[i] = get16(data, kMeasurementHeaderSize + 2 * i);
  }
  return {};
}

}  // namespace rs4sim::rs4::protocol
