#include "gsd/unit_diag.h"

#include "gsd/interp_detail.h"

#include <map>

namespace rs4sim::gsd {

namespace detail {

namespace {

// The device-related block of Max_Diag_Data_Len 244 at most: 244 - 6 standard bytes - 1 header.
constexpr std::int64_t kMaxBit = (244 - 6 - 1) * 8 - 1;

}  // namespace

Result<void> interpret_unit_diag_bit(const std::string& file, const syntax::Statement& st,
                                     UnitDiag& out) {
  const bool not_bit = st.is("Unit_Diag_Not_Bit");
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
                                      UnitDiag& out) {
  const auto& head = entry.statement;
  if (!head.has_equals || head.fields.size() != 1 || head.fields[0].size() != 1 ||
      !head.fields[0][0].is_range()) {
    return error(file, head, GsdError::kBadValue, "Unit_Diag_Area expects a bit range first-last");
  }
  const auto& r = head.fields[0][0];
  if (r.number < 0 || r.high > kMaxBit || r.number > r.high || r.high - r.number > 31) {
    return error(file, head, GsdError::kOutOfRange,
                 "Unit_Diag_Area = " + std::to_string(r.number) + "-" + std::to_string(r.high) +
                     ": bits 0.." + std::to_string(kMaxBit) + ", first <= last, 32 bits at most");
  }
  UnitDiagArea area;
  area.first = static_cast<std::uint16_t>(r.number);
  area.last = static_cast<std::uint16_t>(r.high);
  area.line = head.line;
  const std::int64_t max_value = (std::int64_t{1} << (r.high - r.number + 1)) - 1;
  for (const auto& st : *entry.body) {
    if (!st.is("Value")) continue;  // Value_Help and the like: nothing a master shows
    RS4SIM_GSD_TRY(const auto v, number_arg(file, st, 0, max_value));
    RS4SIM_GSD_TRY(auto text, string_value(file, st));
    if (!area.values.emplace(static_cast<std::uint32_t>(v), std::move(text)).second) {
      return error(file, st, GsdError::kDuplicate, "Value(" + std::to_string(v) + ") given twice");
    }
  }
  out.areas.push_back(std::move(area));
  return boost::outcome_v2::success();
}

}  // namespace detail

std::vector<std::string> unit_diag_texts(const UnitDiag& texts,
                                         std::span<const std::uint8_t> ext_diag) {
  std::vector<std::string> out;
  if (ext_diag.empty() || (ext_diag[0] & 0xC0) != 0) return out;  // not device-related
  const std::size_t length = ext_diag[0] & 0x3F;                  // with the header byte
  if (length < 2 || length > ext_diag.size()) return out;
  const auto data = ext_diag.subspan(1, length - 1);
  const std::size_t bits = data.size() * 8;
  const auto bit = [&](std::size_t n) { return ((data[n / 8] >> (n % 8)) & 1) != 0; };
  // In bit order: bit texts and area texts sorted by their first bit.
  std::multimap<std::size_t, std::string> found;
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
  for (auto& [n, text] : found) out.push_back(std::move(text));
  return out;
}

}  // namespace rs4sim::gsd
