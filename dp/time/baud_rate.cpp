#include "dp/time/baud_rate.h"

#include <cctype>
#include <charconv>

namespace rs4sim::dp {

std::optional<BaudRate> baud_rate_from_bps(std::uint64_t bps) {
  for (BaudRate b : kStandardBaudRates) {
    if (bits_per_second(b) == bps) return b;
  }
  return std::nullopt;
}

std::optional<BaudRate> parse_baud_rate(std::string_view text) {
  if (text.empty()) return std::nullopt;
  std::uint64_t scale = 1;
  const char last = static_cast<char>(std::tolower(static_cast<unsigned char>(text.back())));
  if (last == 'k' || last == 'm') {
    scale = last == 'k' ? 1'000 : 1'000'000;
    text.remove_suffix(1);
  }
  // Integer and up to 3 decimals, no floating point (45.45k must be exact).
  std::uint64_t whole = 0;
  const char* first = text.data();
  const char* end = text.data() + text.size();
  auto [p, ec] = std::from_chars(first, end, whole);
  if (ec != std::errc{} || p == first) return std::nullopt;
  std::uint64_t frac = 0;
  std::uint64_t frac_scale = 1;
  if (p != end) {
    if (*p != '.' || scale == 1) return std::nullopt;
    ++p;
    for (; p != end; ++p) {
      if (!std::isdigit(static_cast<unsigned char>(*p)) || frac_scale >= 1000) return std::nullopt;
      frac = frac * 10 + static_cast<std::uint64_t>(*p - '0');
      frac_scale *= 10;
    }
    if (frac_scale == 1) return std::nullopt;
  }
  if (whole > 100'000'000) return std::nullopt;
  const std::uint64_t bps = whole * scale + frac * scale / frac_scale;
  if (frac * scale % frac_scale != 0) return std::nullopt;
  return baud_rate_from_bps(bps);
}

std::string to_string(BaudRate b) {
  const std::uint32_t bps = bits_per_second(b);
  const auto with_suffix = [](std::uint32_t value, std::uint32_t unit, char suffix) {
    std::string s = std::to_string(value / unit);
    std::uint32_t rest = value % unit;
    if (rest != 0) {
      std::string frac;
      for (std::uint32_t d = unit / 10; d > 0 && rest != 0; d /= 10) {
        frac += static_cast<char>('0' + rest / d);
        rest %= d;
      }
      s += "." + frac;
    }
    return s + suffix;
  };
  return bps >= 1'000'000 ? with_suffix(bps, 1'000'000, 'M') : with_suffix(bps, 1'000, 'k');
}

std::string standard_baud_rate_list() {
  std::string out;
  for (BaudRate b : kStandardBaudRates) {
    if (!out.empty()) out += ", ";
    out += to_string(b);
  }
  return out;
}

Duration bit_time(BaudRate b, std::uint64_t bits) {
  // Exact in integers: ns = ceil(bits * 1e9 / bps); bits < 2^32 keeps this in range.
  const std::uint64_t bps = bits_per_second(b);
  const std::uint64_t ns = (bits * 1'000'000'000ULL + bps - 1) / bps;
  return std::chrono::duration_cast<Duration>(std::chrono::nanoseconds(ns));
}

}  // namespace rs4sim::dp
