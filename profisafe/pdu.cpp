// Safety PDU build and check ([PROFIsafe V1.30 safety PDU] [IEC 61784-3-3 CRC2]). See pdu.h.
#include "profisafe/pdu.h"

#include "codec/reader.h"
#include "codec/writer.h"
#include "profisafe/crc.h"

#include <algorithm>

namespace rs4sim::profisafe {
namespace {

bool covers_number(const PduConfig& c) noexcept {
  switch (c.variant.seq_coverage) {
    case Crc2Variant::SeqCoverage::kAlways: return true;
    case Crc2Variant::SeqCoverage::kNever: return false;
    case Crc2Variant::SeqCoverage::kPerCheckSeqNr: return c.check_seqnr;
  }
  return c.check_seqnr;
}

// V1: the input sequence is [n] + data + sc (kFirst) or data + sc + [n] (kLast).
std::uint32_t crc2_v1(const PduConfig& c, std::span<const std::uint8_t> data, std::uint8_t sc,
                      std::uint8_t number) noexcept {
  const Crc& crc = crc16();
  std::uint32_t reg = c.variant.preset == Crc2Variant::Preset::kCrc1 ? c.crc1 : 0u;
  const bool with_n = covers_number(c);
  const bool n_first = c.variant.seq_position == Crc2Variant::SeqPosition::kFirst;
  const std::array<std::uint8_t, 1> n{number};
  const std::array<std::uint8_t, 1> s{sc};
  if (c.variant.order == Crc2Variant::Order::kForward) {
    if (with_n && n_first) reg = crc.update(reg, n);
    reg = crc.update(reg, data);
    reg = crc.update(reg, s);
    if (with_n && !n_first) reg = crc.update(reg, n);
    return reg;
  }
  // Reversed: the last byte of the sequence first.
  if (with_n && !n_first) reg = crc.update(reg, n);
  reg = crc.update(reg, s);
  reg = crc.update_reversed(reg, data);
  if (with_n && n_first) reg = crc.update(reg, n);
  return reg;
}

// V2 (VERIFIED for the 3-byte CRC2): reverse of [VCN as 4 bytes big-endian] + data + status,
// preset CRC1. The 4-byte CRC2 takes the same input with the CRC-32 (UNCERTAIN, crc.h).
std::uint32_t crc2_v2(const PduConfig& c, std::span<const std::uint8_t> data, std::uint8_t sc,
                      std::uint32_t vcn) noexcept {
  const Crc& crc = c.long_crc2 ? crc32() : crc24();
  const std::array<std::uint8_t, 1> s{sc};
  std::array<std::uint8_t, 4> vcn_reversed{};
  codec::Writer(vcn_reversed).u32_le(vcn);
  std::uint32_t reg = crc.update(c.crc1, s);
  reg = crc.update_reversed(reg, data);
  return crc.update(reg, vcn_reversed);
}

}  // namespace

PduConfig PduConfig::from(const FParameters& p, std::size_t data_size,
                          Crc2Variant variant) noexcept {
  PduConfig c;
  c.version = p.par_version == 1 ? ProtocolVersion::kV2 : ProtocolVersion::kV1;
  c.data_size = data_size;
  c.crc1 = p.par_crc;
  c.check_seqnr = p.check_seqnr;
  c.long_crc2 = p.crc_length == CrcLength::k4Byte;
  c.variant = variant;
  return c;
}

std::size_t crc2_size(const PduConfig& c) noexcept {
  if (c.version == ProtocolVersion::kV1) return 2;
  return c.long_crc2 ? 4 : 3;
}

// V1: status/control + number + 2-byte CRC2; V2: status/control + 3- or 4-byte CRC2.
std::size_t pdu_size(const PduConfig& c) noexcept {
  return c.data_size + 1 + (c.version == ProtocolVersion::kV1 ? 1 : 0) + crc2_size(c);
}

std::error_code check_config(const PduConfig& c) noexcept {
  if (c.data_size == 0 || c.data_size > kMaxDataSize)
    return make_error_code(ProfisafeError::kPduDataTooLong);
  if (c.version != ProtocolVersion::kV1 && c.version != ProtocolVersion::kV2) {
    return make_error_code(ProfisafeError::kPduUnsupportedCrcLength);
  }
  return {};
}

std::uint32_t crc2(const PduConfig& c, std::span<const std::uint8_t> data, std::uint8_t sc,
                   std::uint32_t consecutive_number) noexcept {
  if (c.version == ProtocolVersion::kV2) return crc2_v2(c, data, sc, consecutive_number);
  return crc2_v1(c, data, sc, static_cast<std::uint8_t>(consecutive_number));
}

Result<std::size_t> build_pdu(const PduConfig& c, std::span<const std::uint8_t> data,
                              std::uint8_t sc, std::uint32_t consecutive_number,
                              std::span<std::uint8_t> out) noexcept {
  if (auto ec = check_config(c)) return ec;
  const std::size_t size = pdu_size(c);
  if (data.size() != c.data_size || out.size() < size)
    return make_error_code(ProfisafeError::kPduWrongSize);
  codec::Writer w(out);
  w.bytes(data);
  w.u8(sc);
  if (c.version == ProtocolVersion::kV1) w.u8(static_cast<std::uint8_t>(consecutive_number));
  w.uint_be(crc2(c, data, sc, consecutive_number), crc2_size(c));
  return size;
}

PduCheck check_pdu(const PduConfig& c, std::span<const std::uint8_t> pdu,
                   std::uint32_t vcn) noexcept {
  PduCheck r;
  if (check_config(c) || pdu.size() != pdu_size(c)) {
    r.error = ProfisafeError::kPduWrongSize;
    return r;
  }
  codec::Reader in(pdu);
  r.data = in.bytes(c.data_size);
  r.status_or_control = in.u8();
  std::uint32_t number = vcn;
  if (c.version == ProtocolVersion::kV1) {
    r.consecutive_number = in.u8();
    number = r.consecutive_number;
  }
  r.received_crc2 = in.uint_be(crc2_size(c));
  r.computed_crc2 = crc2(c, r.data, r.status_or_control, number);
  if (r.computed_crc2 != r.received_crc2) r.error = ProfisafeError::kPduCrc2Mismatch;
  return r;
}

std::vector<Crc2Variant> all_crc2_variants() {
  std::vector<Crc2Variant> out;
  for (auto order : {Crc2Variant::Order::kReversed, Crc2Variant::Order::kForward}) {
    for (auto preset : {Crc2Variant::Preset::kCrc1, Crc2Variant::Preset::kZero}) {
      for (auto cov : {Crc2Variant::SeqCoverage::kPerCheckSeqNr, Crc2Variant::SeqCoverage::kAlways,
                       Crc2Variant::SeqCoverage::kNever}) {
        for (auto pos : {Crc2Variant::SeqPosition::kFirst, Crc2Variant::SeqPosition::kLast}) {
          out.push_back(Crc2Variant{order, preset, cov, pos});
        }
      }
    }
  }
  return out;
}

std::vector<Crc2Variant> matching_crc2_variants(
    const PduConfig& base, std::span<const std::span<const std::uint8_t>> pdus) {
  std::vector<Crc2Variant> out;
  for (const Crc2Variant& v : all_crc2_variants()) {
    PduConfig c = base;
    c.version = ProtocolVersion::kV1;
    c.variant = v;
    bool all = true;
    for (const auto& pdu : pdus) {
      if (!check_pdu(c, pdu).ok()) {
        all = false;
        break;
      }
    }
    if (all) out.push_back(v);
  }
  return out;
}

const char* to_string(Crc2Variant::Order v) noexcept {
  return v == Crc2Variant::Order::kReversed ? "reversed" : "forward";
}
const char* to_string(Crc2Variant::Preset v) noexcept {
  return v == Crc2Variant::Preset::kCrc1 ? "preset-crc1" : "preset-zero";
}
const char* to_string(Crc2Variant::SeqCoverage v) noexcept {
  switch (v) {
    case Crc2Variant::SeqCoverage::kPerCheckSeqNr: return "seq-per-F_Check_SeqNr";
    case Crc2Variant::SeqCoverage::kAlways: return "seq-always";
    case Crc2Variant::SeqCoverage::kNever: return "seq-never";
  }
  return "seq-?";
}
const char* to_string(Crc2Variant::SeqPosition v) noexcept {
  return v == Crc2Variant::SeqPosition::kFirst ? "seq-first" : "seq-last";
}

}  // namespace rs4sim::profisafe
