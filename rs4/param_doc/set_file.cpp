#include "rs4/param_doc/set_file.h"

#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

#include <algorithm>
#include <array>
#include <cstdio>

namespace rs4sim::rs4::param_doc {
namespace {

constexpr std::array<std::uint8_t, 4> kTrailerMagic = {0x52, 0x53, 0x34, 0x46};  // "RS4F"
constexpr std::size_t kSetSize = scanner::kParameterSetSize;
constexpr std::size_t kFormat2Size = kSetSize + kSetFileTrailerSize;

std::string hex32(std::uint32_t v) {
  char text[11];
  std::snprintf(text, sizeof text, "0x%08X", v);
  return text;
}

std::uint32_t big_endian32(std::span<const std::uint8_t> b) {
  return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) |
         std::uint32_t{b[3]};
}

SetFileRead refused(std::string why) { return {std::nullopt, std::move(why)}; }

}  // namespace

SetFileRead read_set_file(std::span<const std::uint8_t> file) {
  if (file.size() == kSetSize) {
    return {SetFileBytes{{file.begin(), file.end()}, 1,
                         "a set file of format 1 carries no checksum: a damaged byte cannot be "
                         "told from a change (`rs4sim param set` writes format 2)"},
            {}};
  }
  if (file.size() != kFormat2Size) {
    return refused(std::to_string(file.size()) + " bytes, not a set file (" +
                   std::to_string(kSetSize) + " bytes in format 1, " +
                   std::to_string(kFormat2Size) + " in format 2)");
  }
  const auto trailer = file.subspan(kSetSize);
  if (!std::equal(kTrailerMagic.begin(), kTrailerMagic.end(), trailer.begin())) {
    return refused("damaged: no \"RS4F\" trailer at byte " + std::to_string(kSetSize));
  }
  const auto stored = big_endian32(trailer.subspan(5));
  const auto actual = scanner::crc32_iso_hdlc(file.first(kFormat2Size - 4));
  if (stored != actual) {
    return refused("damaged: its CRC-32 says " + hex32(stored) + ", its contents have " +
                   hex32(actual));
  }
  if (trailer[4] != kSetFileFormat) {
    return refused("set file format " + std::to_string(trailer[4]) +
                   ", this rs4sim reads formats 1 and 2");
  }
  return {SetFileBytes{{file.begin(), file.begin() + kSetSize}, 2, {}}, {}};
}

std::vector<std::uint8_t> set_file(std::span<const std::uint8_t> encoding) {
  std::vector<std::uint8_t> out(encoding.begin(), encoding.end());
  out.insert(out.end(), kTrailerMagic.begin(), kTrailerMagic.end());
  out.push_back(kSetFileFormat);
  const auto crc = scanner::crc32_iso_hdlc(out);
  for (const int shift : {24, 16, 8, 0}) out.push_back(static_cast<std::uint8_t>(crc >> shift));
  return out;
}

}  // namespace rs4sim::rs4::param_doc
