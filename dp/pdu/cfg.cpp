// Configuration identifiers, [IEC 61158-6-3 Chk_Cfg/Get_Cfg].
#include "dp/pdu/cfg.h"

#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {
namespace {

constexpr std::uint8_t kSkipManufacturerCheck = 15;  // Chk_Cfg only

IoLength general_length(std::uint8_t h) {
  return {static_cast<std::uint8_t>((h & 0x0FU) + 1U), wire::bit(h, 6), wire::bit(h, 7)};
}

// Special-format length byte: bit 7 consistent, bit 6 words, bits 5..0 count − 1.
IoLength special_length(std::uint8_t b) {
  return {static_cast<std::uint8_t>((b & 0x3FU) + 1U), wire::bit(b, 6), wire::bit(b, 7)};
}

std::uint8_t special_length_byte(const IoLength& l) {
  return static_cast<std::uint8_t>(wire::flag(l.consistent, 7) | wire::flag(l.words, 6) |
                                   ((l.count - 1U) & 0x3FU));
}

Result<CfgParse> decode_special(std::span<const std::uint8_t> du, CfgService service) {
  const std::uint8_t h = du[0];
  const unsigned length_bytes = (h >> 6) & 0x03U;  // 1 in, 2 out, 3 out then in
  const unsigned manufacturer = h & 0x0FU;
  CfgParse p;
  p.identifier.format = CfgFormat::kSpecial;
  std::size_t pos = 1;
  const std::size_t need = 1 + (length_bytes == 3 ? 2U : length_bytes != 0 ? 1U : 0U);
  if (du.size() < need) return PduError::kTooShort;
  if ((length_bytes & 0x02U) != 0) p.identifier.output = special_length(du[pos++]);
  if ((length_bytes & 0x01U) != 0) p.identifier.input = special_length(du[pos++]);
  if (manufacturer == kSkipManufacturerCheck) {
    if (service == CfgService::kGetCfg) return PduError::kBadIdentifier;
    p.identifier.skip_manufacturer_check = true;
  } else {
    if (du.size() < pos + manufacturer) return PduError::kTooShort;
    p.identifier.manufacturer_data.assign(
        du.begin() + static_cast<std::ptrdiff_t>(pos),
        du.begin() + static_cast<std::ptrdiff_t>(pos + manufacturer));
    pos += manufacturer;
  }
  p.size = pos;
  return p;
}

Result<void> check_count(const std::optional<IoLength>& l, unsigned max) {
  if (l && (l->count == 0 || l->count > max)) return PduError::kBadIdentifier;
  return boost::outcome_v2::success();
}

Result<void> encode_general(const CfgIdentifier& id, fdl::DataUnit& out) {
  if (!id.input && !id.output) return PduError::kBadIdentifier;
  if (id.input && id.output && !(*id.input == *id.output)) return PduError::kBadIdentifier;
  if (!id.manufacturer_data.empty() || id.skip_manufacturer_check) return PduError::kBadIdentifier;
  BOOST_OUTCOME_TRY(check_count(id.input, 16));
  BOOST_OUTCOME_TRY(check_count(id.output, 16));
  const IoLength& l = id.input ? *id.input : *id.output;
  const unsigned dir = (id.input ? 1U : 0U) | (id.output ? 2U : 0U);
  return wire::append(
      out, {static_cast<std::uint8_t>(wire::flag(l.consistent, 7) | wire::flag(l.words, 6) |
                                      (dir << 4) | ((l.count - 1U) & 0x0FU))});
}

Result<void> encode_special(const CfgIdentifier& id, fdl::DataUnit& out) {
  BOOST_OUTCOME_TRY(check_count(id.input, 64));
  BOOST_OUTCOME_TRY(check_count(id.output, 64));
  if (id.skip_manufacturer_check && !id.manufacturer_data.empty()) return PduError::kBadIdentifier;
  const unsigned length_bytes = (id.input ? 1U : 0U) | (id.output ? 2U : 0U);
  const unsigned manufacturer = id.skip_manufacturer_check
                                    ? kSkipManufacturerCheck
                                    : static_cast<unsigned>(id.manufacturer_data.size());
  if (out.size() + id.encoded_size() > wire::kMaxDpDu) return PduError::kTooLong;
  (void)wire::append(out, {static_cast<std::uint8_t>((length_bytes << 6) | manufacturer)});
  if (id.output) (void)wire::append(out, {special_length_byte(*id.output)});
  if (id.input) (void)wire::append(out, {special_length_byte(*id.input)});
  return wire::append(out, id.manufacturer_data);
}

}  // namespace

std::size_t CfgIdentifier::encoded_size() const {
  if (format == CfgFormat::kGeneral) return 1;
  return 1U + (input ? 1U : 0U) + (output ? 1U : 0U) + manufacturer_data.size();
}

Result<CfgParse> decode_cfg_identifier(std::span<const std::uint8_t> du, CfgService service) {
  if (du.empty()) return PduError::kTooShort;
  const std::uint8_t h = du[0];
  if ((h & 0x30U) == 0) return decode_special(du, service);
  CfgParse p;
  p.identifier.format = CfgFormat::kGeneral;
  if ((h & 0x10U) != 0) p.identifier.input = general_length(h);
  if ((h & 0x20U) != 0) p.identifier.output = general_length(h);
  p.size = 1;
  return p;
}

Result<CfgSummary> summarize_cfg(std::span<const std::uint8_t> du, CfgService service) {
  if (du.empty() && service == CfgService::kChkCfg) return PduError::kTooShort;
  if (du.size() > kCfgMaxLength) return PduError::kTooLong;
  CfgSummary s;
  while (!du.empty()) {
    BOOST_OUTCOME_TRY(p, decode_cfg_identifier(du, service));
    ++s.identifiers;
    s.input_bytes += p.identifier.input_bytes();
    s.output_bytes += p.identifier.output_bytes();
    du = du.subspan(p.size);
  }
  return s;
}

Result<void> encode_cfg_identifier(const CfgIdentifier& id, fdl::DataUnit& out) {
  return id.format == CfgFormat::kGeneral ? encode_general(id, out) : encode_special(id, out);
}

CfgIdentifier general_input(std::uint8_t count, bool words, bool consistent) {
  CfgIdentifier id;
  id.input = IoLength{count, words, consistent};
  return id;
}

CfgIdentifier general_output(std::uint8_t count, bool words, bool consistent) {
  CfgIdentifier id;
  id.output = IoLength{count, words, consistent};
  return id;
}

CfgIdentifier general_input_output(std::uint8_t count, bool words, bool consistent) {
  CfgIdentifier id;
  id.input = IoLength{count, words, consistent};
  id.output = id.input;
  return id;
}

CfgIdentifier empty_slot() {
  CfgIdentifier id;
  id.format = CfgFormat::kSpecial;
  return id;
}

}  // namespace rs4sim::dp::pdu
