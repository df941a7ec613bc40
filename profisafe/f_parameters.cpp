// F-parameter block: codec and validation ([IEC 61784-3-3 F-Parameters, CRC1]). See f_parameters.h.
#include "profisafe/f_parameters.h"

#include "codec/endian.h"
#include "codec/reader.h"
#include "codec/writer.h"
#include "profisafe/crc.h"

namespace rs4sim::profisafe {
namespace {

constexpr std::uint8_t kFlag1Reserved = 0xC0;  // F_Prm_Flag1 b6-7
constexpr std::uint8_t kFlag2Reserved = 0x07;  // F_Prm_Flag2 b0-2

constexpr bool valid_address(std::uint16_t a) noexcept { return a != 0 && a != 0xFFFF; }

}  // namespace

std::array<std::uint8_t, 8> encode_f_parameters_without_crc(const FParameters& p) noexcept {
  std::array<std::uint8_t, 8> b{};
  codec::Writer w(b);
  w.u8(static_cast<std::uint8_t>((p.check_seqnr ? 0x01 : 0x00) | (p.check_ipar ? 0x02 : 0x00) |
                                 ((static_cast<unsigned>(p.sil) & 0x3u) << 2) |
                                 ((static_cast<unsigned>(p.crc_length) & 0x3u) << 4)));
  w.u8(static_cast<std::uint8_t>(((p.block_id & 0x7u) << 3) | ((p.par_version & 0x3u) << 6)));
  w.u16_be(p.source_add);
  w.u16_be(p.dest_add);
  w.u16_be(p.wd_time_ms);
  return b;
}

std::uint16_t crc1(const FParameters& p) noexcept {
  const auto b = encode_f_parameters_without_crc(p);
  return crc1(std::span<const std::uint8_t, 8>(b), p.ipar_crc);
}

std::array<std::uint8_t, kFParametersSize> encode_f_parameters_raw(const FParameters& p) noexcept {
  std::array<std::uint8_t, kFParametersSize> out{};
  const auto b = encode_f_parameters_without_crc(p);
  codec::Writer w(out);
  w.bytes(b);
  w.u16_be(p.par_crc);
  return out;
}

std::array<std::uint8_t, kFParametersSize> encode_f_parameters(const FParameters& p) noexcept {
  FParameters q = p;
  q.par_crc = crc1(p);
  return encode_f_parameters_raw(q);
}

Result<FParameters> parse_f_parameters(std::span<const std::uint8_t> block,
                                       std::optional<std::uint32_t> ipar_crc) {
  if (block.size() != kFParametersSize) return make_error_code(ProfisafeError::kFParamsWrongSize);
  if ((block[0] & kFlag1Reserved) != 0 || (block[1] & kFlag2Reserved) != 0) {
    return make_error_code(ProfisafeError::kFParamsReservedBits);
  }
  FParameters p;
  p.check_seqnr = (block[0] & 0x01) != 0;
  p.check_ipar = (block[0] & 0x02) != 0;
  p.sil = static_cast<Sil>((block[0] >> 2) & 0x3);
  p.crc_length = static_cast<CrcLength>((block[0] >> 4) & 0x3);
  p.block_id = static_cast<std::uint8_t>((block[1] >> 3) & 0x7);
  p.par_version = static_cast<std::uint8_t>((block[1] >> 6) & 0x3);
  if (ipar_crc && p.par_version != 1)
    return make_error_code(ProfisafeError::kFParamsIParCrcNeedsV2);
  codec::Reader r(block.subspan(2));
  p.source_add = r.u16_be();
  p.dest_add = r.u16_be();
  p.wd_time_ms = r.u16_be();
  p.par_crc = r.u16_be();
  p.ipar_crc = ipar_crc;
  return p;
}

DeviceProfile profile_for(const FParameters& p) noexcept {
  return DeviceProfile{.check_ipar = p.check_ipar,
                       .sil = p.sil,
                       .crc_length = p.crc_length,
                       .block_id = p.block_id,
                       .par_version = p.par_version,
                       .dest_add = p.dest_add};
}

Validation validate(const FParameters& p, const DeviceProfile& d) noexcept {
  Validation v;
  v.received_crc1 = p.par_crc;
  v.computed_crc1 = crc1(p);
  auto fail = [&v](FParameterFault fault) {
    v.fault = fault;
    return v;
  };
  // The first failing check, in the enum's order.
  if (!valid_address(d.dest_add)) return fail(FParameterFault::kDestAddInvalid);
  if (p.dest_add != d.dest_add) return fail(FParameterFault::kDestAddMismatch);
  if (!valid_address(p.source_add) || p.source_add < d.min_source_add ||
      p.source_add > d.max_source_add) {
    return fail(FParameterFault::kSourceAddInvalid);
  }
  if (p.wd_time_ms < d.min_wd_time_ms || p.wd_time_ms > d.max_wd_time_ms)
    return fail(FParameterFault::kWdTimeInvalid);
  if (p.sil != d.sil) return fail(FParameterFault::kSilMismatch);
  if (p.crc_length != d.crc_length) return fail(FParameterFault::kCrcLengthMismatch);
  if (p.block_id != d.block_id || p.par_version != d.par_version || p.check_ipar != d.check_ipar) {
    return fail(FParameterFault::kVersionMismatch);
  }
  if (v.received_crc1 != v.computed_crc1) return fail(FParameterFault::kCrc1Mismatch);
  return v;
}

Validation validate(std::span<const std::uint8_t> block, const DeviceProfile& d) noexcept {
  auto parsed = parse_f_parameters(block);
  if (!parsed) {
    Validation v;
    v.fault = FParameterFault::kVersionMismatch;
    if (block.size() == kFParametersSize) {
      v.received_crc1 = codec::be16(block[8], block[9]);
      v.computed_crc1 = crc1(block.first<8>());
    }
    return v;
  }
  return validate(parsed.value(), d);
}

const char* to_string(FParameterFault f) noexcept {
  switch (f) {
    case FParameterFault::kNone: return "no error";
    case FParameterFault::kDestAddInvalid: return "internal F_Dest_Add error";
    case FParameterFault::kDestAddMismatch: return "wrong F_Dest_Add";
    case FParameterFault::kSourceAddInvalid: return "wrong F_Source_Add";
    case FParameterFault::kWdTimeInvalid: return "wrong F_WD_Time";
    case FParameterFault::kSilMismatch: return "wrong SIL";
    case FParameterFault::kCrcLengthMismatch: return "wrong CRC length";
    case FParameterFault::kVersionMismatch: return "wrong F_Block_ID or F_Par_Version";
    case FParameterFault::kCrc1Mismatch: return "wrong CRC1 over the F-parameters";
  }
  return "unknown F-parameter fault";
}

// V1: F_Par_Version 0 with the 2-byte CRC2; V2: F_Par_Version 1 with the 3- or 4-byte CRC2.
bool is_supported_connection(std::uint8_t par_version, CrcLength crc_length) noexcept {
  if (par_version == 0) return crc_length == CrcLength::k2Byte;
  return par_version == 1 && (crc_length == CrcLength::k3Byte || crc_length == CrcLength::k4Byte);
}

std::uint8_t standard_diagnosis(FParameterFault f) noexcept {
  switch (f) {
    case FParameterFault::kNone: return 0;
    case FParameterFault::kDestAddMismatch: return 64;
    case FParameterFault::kDestAddInvalid: return 65;
    case FParameterFault::kSourceAddInvalid: return 66;
    case FParameterFault::kWdTimeInvalid: return 67;
    case FParameterFault::kSilMismatch: return 68;
    case FParameterFault::kCrcLengthMismatch: return 69;
    case FParameterFault::kVersionMismatch: return 70;
    case FParameterFault::kCrc1Mismatch: return 71;
  }
  return 0;
}

const char* standard_diagnosis_text(std::uint8_t diagnosis) noexcept {
  switch (diagnosis) {
    case 64: return "Mismatch of safety destination address (F_Dest_Add)";
    case 65: return "Safety destination address not valid (F_Dest_Add)";
    case 66: return "Safety source address not valid (F_Source_Add)";
    case 67: return "Safety watchdog time value is 0 ms or not supported (F_WD_Time)";
    case 68: return "Parameter F_SIL exceeds SIL from specific device application";
    case 69: return "Parameter F_CRC_Length does not match the generated values";
    case 70: return "Version of F-parameter set incorrect";
    case 71: return "CRC1 fault (F_Par_CRC)";
    default: return "";
  }
}

}  // namespace rs4sim::profisafe
