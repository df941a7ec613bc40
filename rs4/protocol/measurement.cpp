#include "rs4/protocol/measurement.h"

#include "codec/reader.h"
#include "codec/writer.h"

namespace rs4sim::rs4::protocol {
namespace {

using Appender = codec::Appender<std::vector<std::uint8_t>>;

// Scan number, resolution, start, stop (table 5.2-14 bytes 9..21).
void put_header(std::uint32_t scan, std::uint8_t resolution, std::uint16_t start,
                std::uint16_t stop, Appender& w) {
  for (unsigned n = 4; n-- > 0;) {
    w.u8(codec::byte_of(scan, n));
    w.u8(kScanNumberFiller);  // keeps small numbers from making runs of zeros
  }
  w.u8(resolution);
  w.u16_be(start);
  w.u16_be(stop);
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
  Appender w(out);
  put_header(t.scan_number, t.resolution, t.start, t.stop, w);
  for (const auto value : t.values) w.u16_be(value);
  return {};
}

std::error_code encode_measurement_data(std::uint32_t scan_number, std::uint8_t resolution,
                                        std::uint16_t start, std::uint16_t stop,
                                        std::span<const std::uint16_t, kContourSegments> contour,
                                        std::vector<std::uint8_t>& out) {
  auto count = measurement_value_count(start, stop, resolution);
  if (!count) return count.error();
  out.reserve(out.size() + kMeasurementHeaderSize + 2 * count.value());
  Appender w(out);
  put_header(scan_number, resolution, start, stop, w);
  std::size_t segment = start;
  for (; segment < stop; segment += resolution) w.u16_be(contour[segment]);
  w.u16_be(contour[stop]);  // the stop segment is always output ([RS4 manual §5.2.3.4])
  return {};
}

std::error_code decode_measurement_data(std::span<const std::uint8_t> data,
                                        MeasurementTelegram& t) {
  if (data.size() < kMeasurementHeaderSize) return ProtocolError::kTruncated;
  codec::Reader r(data);
  std::uint32_t scan = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    scan = (scan << 8U) | r.u8();
    if (r.u8() != kScanNumberFiller) return ProtocolError::kBadScanNumberFiller;
  }
  t.scan_number = scan;
  t.resolution = r.u8();
  t.start = r.u16_be();
  t.stop = r.u16_be();
  auto count = measurement_value_count(t.start, t.stop, t.resolution);
  if (!count) return count.error();
  if (r.remaining() < 2 * count.value()) return ProtocolError::kTruncated;
  if (r.remaining() > 2 * count.value()) return ProtocolError::kTrailingBytes;
  t.values.resize(count.value());
  r.u16_be_array(t.values);
  return {};
}

}  // namespace rs4sim::rs4::protocol
