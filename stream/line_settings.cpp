#include "stream/line_settings.h"

#include <cmath>

namespace rs4sim::stream {

Duration character_time(const LineSettings& s, double characters) {
  const double ns = characters * bits_per_character(s) * 1e9 / static_cast<double>(s.baud);
  return std::chrono::duration_cast<Duration>(
      std::chrono::nanoseconds(static_cast<std::int64_t>(std::ceil(ns))));
}

std::string to_string(const LineSettings& s) {
  const char parity = s.parity == Parity::kNone ? 'N' : (s.parity == Parity::kEven ? 'E' : 'O');
  std::string out = std::to_string(s.baud) + ' ';
  out += static_cast<char>('0' + s.data_bits);
  out += parity;
  out += static_cast<char>('0' + s.stop_bits);
  return out;
}

bool parse_format(std::string_view text, LineSettings& s) {
  if (text.size() != 3) return false;
  if (text[0] < '5' || text[0] > '8') return false;
  Parity parity{};
  switch (text[1]) {
    case 'N':
    case 'n': parity = Parity::kNone; break;
    case 'E':
    case 'e': parity = Parity::kEven; break;
    case 'O':
    case 'o': parity = Parity::kOdd; break;
    default: return false;
  }
  if (text[2] != '1' && text[2] != '2') return false;
  s.data_bits = static_cast<std::uint8_t>(text[0] - '0');
  s.parity = parity;
  s.stop_bits = static_cast<std::uint8_t>(text[2] - '0');
  return true;
}

}  // namespace rs4sim::stream
