// Fuzzes the RS4 telegram decoder ([RS4 manual §5.2.3, §5.2.3.4]): decode → encode →
// decode must give the same telegram; the measurement encoder from a contour must agree
// with the value-list encoder.
#include "rs4/protocol/telegram.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

using namespace rs4sim::rs4::protocol;

namespace {

void check(bool ok) {
  if (!ok) __builtin_trap();
}

void contour_agrees(const MeasurementTelegram& m) {
  std::array<std::uint16_t, kContourSegments> contour{};
  std::size_t i = 0;
  for (std::size_t s = m.start; s < m.stop; s += m.resolution) contour[s] = m.values[i++];
  contour[m.stop] = m.values.back();
  std::vector<std::uint8_t> a;
  std::vector<std::uint8_t> b;
  check(!encode_measurement_data(m, a));
  check(!encode_measurement_data(m.scan_number, m.resolution, m.start, m.stop, contour, b));
  check(a == b);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);
  auto decoded = decode_telegram(in);
  if (!decoded) return 0;
  auto encoded = encode_telegram(decoded.value());
  check(static_cast<bool>(encoded));
  auto again = decode_telegram(encoded.value());
  check(again && again.value() == decoded.value());
  if (const auto* m = std::get_if<MeasurementTelegram>(&decoded.value())) contour_agrees(*m);
  return 0;
}
