#pragma once
// Test-side reader of a bus capture stored as text: the word `start`, one NUL byte, then the
// line's bytes as one hexadecimal string (no timestamps, no telegram boundaries), the way a
// sniffer of the NIKI 4.0 project wrote what it read off a real PROFIBUS line (docs/capture.md
// "Real bus traffic"). A trailing odd digit is half a byte and is dropped.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::dp::fdl::testing {

struct HexCapture {
  std::vector<std::uint8_t> bytes;
  std::size_t digits = 0;  // hex digits after the header
};

inline int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// nullopt with `error` set when the file cannot be read, has no `start\0` header or holds a
// character that is no hex digit (trailing line ends allowed).
inline std::optional<HexCapture> read_hex_capture(const std::filesystem::path& path,
                                                  std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = path.string() + ": cannot read";
    return std::nullopt;
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  constexpr std::string_view kHeader("start\0", 6);
  if (text.compare(0, kHeader.size(), kHeader) != 0) {
    error = path.string() + ": no 'start' NUL header";
    return std::nullopt;
  }
  std::string_view hex = std::string_view(text).substr(kHeader.size());
  while (!hex.empty() && (hex.back() == '\n' || hex.back() == '\r')) hex.remove_suffix(1);
  HexCapture out;
  out.digits = hex.size();
  out.bytes.reserve(hex.size() / 2);
  for (std::size_t i = 0; i < hex.size(); ++i) {
    const int d = hex_digit(hex[i]);
    if (d < 0) {
      error = "offset " + std::to_string(kHeader.size() + i) + ": not a hex digit";
      return std::nullopt;
    }
    if (i % 2 == 1) {
      const int high = hex_digit(hex[i - 1]);
      out.bytes.push_back(static_cast<std::uint8_t>(high * 16 + d));
    }
  }
  return out;
}

}  // namespace rs4sim::dp::fdl::testing
