#include "rs4/scanner/parameter_codec.h"

#include "codec/reader.h"
#include "codec/writer.h"
#include "rs4/scanner/crc32.h"

#include <algorithm>

namespace rs4sim::rs4::scanner {
namespace {

constexpr std::array<std::uint8_t, 4> kMagic{'R', 'S', '4', 'P'};

using Writer = codec::Appender<std::vector<std::uint8_t>>;
using Reader = codec::Reader;

void write_header(Writer& w, const ParameterSet& s) {
  for (const auto b : kMagic) w.u8(b);
  w.u8(kParameterFormatVersion);
  w.u8(0);  // reserved
  w.u32_be(s.identity.serial_number);
  w.u16_be(s.identity.device_type);
  w.u8(s.identity.firmware_major);
  w.u8(s.identity.firmware_minor);
  w.u8(s.response_steps);
  w.u8(static_cast<std::uint8_t>(s.restart_mode));
  w.u8(s.start_pair);
  for (const auto row : s.permitted) w.u8(row);
  w.u8(s.warning_output);
  w.u8(s.measurement.resolution);
  w.u16_be(s.measurement.start);
  w.u16_be(s.measurement.stop);
  for (const auto& pw : s.passwords) {
    for (const auto b : pw) w.u8(b);
  }
}

void read_header(Reader& r, ParameterSet& s) {
  s.identity.serial_number = r.u32_be();
  s.identity.device_type = r.u16_be();
  s.identity.firmware_major = r.u8();
  s.identity.firmware_minor = r.u8();
  s.response_steps = r.u8();
  s.restart_mode = static_cast<RestartMode>(r.u8());
  s.start_pair = r.u8();
  for (auto& row : s.permitted) row = r.u8();
  s.warning_output = r.u8();
  s.measurement.resolution = r.u8();
  s.measurement.start = r.u16_be();
  s.measurement.stop = r.u16_be();
  for (auto& pw : s.passwords) {
    for (auto& b : pw) b = r.u8();
  }
}

}  // namespace

std::vector<std::uint8_t> encode(const ParameterSet& set) {
  std::vector<std::uint8_t> out;
  out.reserve(kParameterSetSize);
  Writer w(out);
  write_header(w, set);
  for (const FieldPair& fp : set.pairs) {
    for (const auto v : fp.protective_mm) w.u16_be(v);
    for (const auto v : fp.warning_mm) w.u16_be(v);
  }
  return out;
}

boost::outcome_v2::std_result<ParameterSet> decode(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < kParameterSetSize) return CodecError::kTooShort;
  if (bytes.size() > kParameterSetSize) return CodecError::kTooLong;
  if (!std::equal(kMagic.begin(), kMagic.end(), bytes.begin())) return CodecError::kBadMagic;
  if (bytes[4] != kParameterFormatVersion) return CodecError::kUnsupportedVersion;
  if (bytes[5] != 0) return CodecError::kReservedNotZero;
  ParameterSet s;
  Reader r(bytes.subspan(6));
  read_header(r, s);
  for (FieldPair& fp : s.pairs) {
    r.u16_be_array(fp.protective_mm);
    r.u16_be_array(fp.warning_mm);
  }
  return s;
}

boost::outcome_v2::std_result<ParameterSet> decode_and_validate(
    std::span<const std::uint8_t> bytes) {
  auto decoded = decode(bytes);
  if (!decoded) return decoded.error();
  if (const auto issue = validate(decoded.value())) return issue->error;
  return decoded;
}

std::uint32_t checksum(const ParameterSet& set) { return crc32_iso_hdlc(encode(set)); }

std::vector<std::uint8_t> encode_for_transfer(const ParameterSet& set) {
  ParameterSet blank = set;
  blank.identity = Identity{};
  for (auto& pw : blank.passwords) pw.fill(0x00);
  return encode(blank);
}

std::uint32_t transfer_checksum(const ParameterSet& set) {
  return crc32_iso_hdlc(encode_for_transfer(set));
}

boost::outcome_v2::std_result<ParameterSet> decode_transfer_form(
    std::span<const std::uint8_t> bytes) {
  auto set = decode(bytes);
  if (!set) return set.error();
  ParameterSet check = set.value();
  for (auto& pw : check.passwords) pw.fill(0xFF);  // an empty password
  if (const auto issue = validate(check)) return make_error_code(issue->error);
  return set;
}

}  // namespace rs4sim::rs4::scanner
