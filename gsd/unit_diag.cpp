#include "gsd/unit_diag.h"

#include "gsd/interp_detail.h"
#include "profisafe/f_parameters.h"

#include <map>

namespace rs4sim::gsd {

namespace detail {

namespace {

// The device-related block of Max_Diag_Data_Len 244 at most: 244 - 6 standard bytes - 1 header.
constexpr std::int64_t kMaxBit = (244 - 6 - 1) * 8 - 1;

}  // namespace

Result<void> interpret_unit_diag_bit(const std::string& file, const syntax::Statement& st,
                                     UnitDiagTexts& out) {
  const bool not_bit = st.is("Unit_Diag_Not_Bit") || st.is("X_Unit_Diag_Not_Bit");
  RS4SIM_GSD_TRY(const auto bit, number_arg(file, st, 0, kMaxBit));
  RS4SIM_GSD_TRY(auto text, string_value(file, st));
  auto& map = not_bit ? out.not_bits : out.bits;
  if (!map.emplace(static_cast<std::uint16_t>(bit), std::move(text)).second) {
    return error(file, st, GsdError::kDuplicate,
                 st.keyword + "(" + std::to_string(bit) + ") given twice");
  }
  return boost::outcome_v2::success();
}

Result<void> interpret_unit_diag_area(const std::string& file, const syntax::Entry& entry,
                                      UnitDiagTexts& out) {
  const auto& head = entry.statement;
  if (!head.has_equals || head.fields.size() != 1 || head.fields[0].size() != 1 ||
      !head.fields[0][0].is_range()) {
    return error(file, head, GsdError::kBadValue, head.keyword + " expects a bit range first-last");
  }
  const auto& r = head.fields[0][0];
  if (r.number < 0 || r.high > kMaxBit || r.number > r.high || r.high - r.number > 31) {
    return error(file, head, GsdError::kOutOfRange,
                 head.keyword + " = " + std::to_string(r.number) + "-" + std::to_string(r.high) +
                     ": bits 0.." + std::to_string(kMaxBit) + ", first <= last, 32 bits at most");
  }
  UnitDiagArea area;
  area.first = static_cast<std::uint16_t>(r.number);
  area.last = static_cast<std::uint16_t>(r.high);
  area.line = head.line;
  const std::int64_t max_value = (std::int64_t{1} << (r.high - r.number + 1)) - 1;
  for (const auto& st : *entry.body) {
    // Value_Help and the like: nothing a master shows
    if (!st.is("Value") && !st.is("X_Value")) continue;
    RS4SIM_GSD_TRY(const auto v, number_arg(file, st, 0, max_value));
    RS4SIM_GSD_TRY(auto text, string_value(file, st));
    if (!area.values.emplace(static_cast<std::uint32_t>(v), std::move(text)).second) {
      return error(file, st, GsdError::kDuplicate, "Value(" + std::to_string(v) + ") given twice");
    }
  }
  out.areas.push_back(std::move(area));
  return boost::outcome_v2::success();
}

// The lines of a UnitDiagType block: bit lines, and area blocks whose head, values and End line
// stand flat in the body (syntax::File keeps a nested block so).
Result<void> interpret_unit_diag_type(const std::string& file, const syntax::Entry& entry,
                                      UnitDiag& out, std::vector<Warning>& warnings) {
  RS4SIM_GSD_TRY(const auto type, number(file, entry.statement, 0, 255));
  UnitDiagTexts& texts = out.types[static_cast<std::uint8_t>(type)];
  const auto& body = *entry.body;
  for (std::size_t i = 0; i < body.size(); ++i) {
    const auto& st = body[i];
    if (st.is("Unit_Diag_Bit") || st.is("Unit_Diag_Not_Bit") || st.is("X_Unit_Diag_Bit") ||
        st.is("X_Unit_Diag_Not_Bit")) {
      RS4SIM_GSD_TRYV(forgive(warnings, interpret_unit_diag_bit(file, st, texts)));
    } else if (st.is("Unit_Diag_Area") || st.is("X_Unit_Diag_Area")) {
      syntax::Entry area{st, std::vector<syntax::Statement>{}};
      for (++i; i < body.size() && !body[i].is(st.keyword + "_End"); ++i) {
        area.body->push_back(body[i]);
      }
      RS4SIM_GSD_TRYV(forgive(warnings, interpret_unit_diag_area(file, area, texts)));
    }
  }
  return boost::outcome_v2::success();
}

Result<void> interpret_channel_diag(const std::string& file, const syntax::Statement& st,
                                    UnitDiag& out) {
  // Error types 16..31 are the manufacturer's [IEC 61158-6-3 Slave_Diag channel diagnosis].
  RS4SIM_GSD_TRY(const auto type, number_arg(file, st, 16, 31));
  RS4SIM_GSD_TRY(auto text, string_value(file, st));
  if (!out.channel_errors.emplace(static_cast<std::uint8_t>(type), std::move(text)).second) {
    return error(file, st, GsdError::kDuplicate, "Channel_Diag(" + std::to_string(type) +
                                                     ") given twice");
  }
  return boost::outcome_v2::success();
}

}  // namespace detail

namespace {

// The texts of `texts` for the bits of `data` (the block after its header), by first bit.
void collect(const UnitDiagTexts& texts, std::span<const std::uint8_t> data,
             std::multimap<std::size_t, std::string>& found) {
  const std::size_t bits = data.size() * 8;
  const auto bit = [&](std::size_t n) { return ((data[n / 8] >> (n % 8)) & 1) != 0; };
  for (const auto& [n, text] : texts.bits) {
    if (n < bits && bit(n)) found.emplace(n, text);
  }
  for (const auto& [n, text] : texts.not_bits) {
    if (n < bits && !bit(n)) found.emplace(n, text);
  }
  for (const auto& a : texts.areas) {
    if (a.last >= bits) continue;
    std::uint32_t v = 0;
    for (std::size_t n = a.last + 1; n-- > a.first;) v = (v << 1) | (bit(n) ? 1U : 0U);
    const auto it = a.values.find(v);
    found.emplace(a.first, it != a.values.end()
                               ? it->second
                               : "Unit_Diag_Area " + std::to_string(a.first) + "-" +
                                     std::to_string(a.last) + ": value " + std::to_string(v));
  }
}

}  // namespace

std::vector<std::string> unit_diag_texts(const UnitDiag& texts,
                                         std::span<const std::uint8_t> ext_diag) {
  std::vector<std::string> out;
  if (ext_diag.empty() || (ext_diag[0] & 0xC0) != 0) return out;  // not device-related
  const std::size_t length = ext_diag[0] & 0x3F;                  // with the header byte
  if (length < 2 || length > ext_diag.size()) return out;
  const auto data = ext_diag.subspan(1, length - 1);
  // In bit order: bit texts and area texts sorted by their first bit, the block type's with
  // the others.
  std::multimap<std::size_t, std::string> found;
  collect(texts, data, found);
  if (const auto type = texts.types.find(data[0]); type != texts.types.end()) {
    collect(type->second, data, found);
  }
  for (auto& [n, text] : found) out.push_back(std::move(text));
  return out;
}

namespace {

// The GSD's own text of F-diagnosis `number`, nullptr when it names none.
const std::string* gsd_f_text(const UnitDiag& texts, std::uint8_t number) {
  constexpr std::uint8_t kStatusMessage = 0x81;  // [IEC 61158-6-3 DPV1 status] Status_Type
  const auto find = [number](const UnitDiagTexts& t) -> const std::string* {
    for (const auto& a : t.areas) {
      if (a.first != 24 || a.last != 31) continue;
      const auto it = a.values.find(number);
      if (it != a.values.end()) return &it->second;
    }
    return nullptr;
  };
  if (const auto type = texts.types.find(kStatusMessage); type != texts.types.end()) {
    if (const std::string* t = find(type->second)) return t;
  }
  return find(texts);
}

}  // namespace

std::string f_diagnosis_text(const UnitDiag& texts, std::uint8_t number) {
  if (const std::string* own = gsd_f_text(texts, number); own != nullptr && number != 0) {
    return *own;
  }
  return profisafe::standard_diagnosis_text(number);
}

std::vector<std::string> device_diag_texts(const UnitDiag& texts, bool f_device,
                                           std::span<const std::uint8_t> ext_diag) {
  std::vector<std::string> out = unit_diag_texts(texts, ext_diag);
  // `05 81 slot 00 nn`: a device-related block of 5 bytes, status type 0x81, specifier 0.
  if (!f_device || ext_diag.size() < 5 || ext_diag[0] != 0x05 || ext_diag[1] != 0x81 ||
      ext_diag[3] != 0x00) {
    return out;
  }
  const std::uint8_t number = ext_diag[4];
  const std::string standard = profisafe::standard_diagnosis_text(number);
  if (!standard.empty() && gsd_f_text(texts, number) == nullptr) out.push_back(standard);
  return out;
}

std::string channel_error_text(const UnitDiag& texts, std::uint8_t error_type) {
  const auto it = texts.channel_errors.find(error_type);
  return it != texts.channel_errors.end() ? it->second : std::string();
}

}  // namespace rs4sim::gsd
