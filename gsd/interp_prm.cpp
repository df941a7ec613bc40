// ExtUserPrmData and PrmText blocks ([PROFIBUS GSD spec general keywords]).
#include "gsd/interp_detail.h"

#include <algorithm>
#include <array>

namespace rs4sim::gsd::detail {
namespace {

struct TypeInfo {
  std::string_view keyword;
  ParamType type;
  std::int64_t lo;
  std::int64_t hi;
};

constexpr std::array<TypeInfo, 6> kByteTypes{{
    {"Unsigned8", ParamType::kUnsigned8, 0, 0xFF},
    {"Unsigned16", ParamType::kUnsigned16, 0, 0xFFFF},
    {"Unsigned32", ParamType::kUnsigned32, 0, 0xFFFFFFFF},
    {"Signed8", ParamType::kSigned8, -0x80, 0x7F},
    {"Signed16", ParamType::kSigned16, -0x8000, 0x7FFF},
    {"Signed32", ParamType::kSigned32, -0x80000000LL, 0x7FFFFFFF},
}};

bool is_type_line(const syntax::Statement& st) {
  if (st.is("Bit") || st.is("BitArea")) return true;
  for (const auto& t : kByteTypes) {
    if (st.is(t.keyword)) return true;
  }
  return false;
}

// Sets type, bits and the value range the type itself allows.
Result<std::pair<std::int64_t, std::int64_t>> read_type(const std::string& file,
                                                        const syntax::Statement& st, ExtParam& p) {
  if (st.is("Bit")) {
    RS4SIM_GSD_TRY(const auto bit, number_arg(file, st, 0, 7));
    p.type = ParamType::kBit;
    p.bit_low = p.bit_high = static_cast<int>(bit);
    return std::pair<std::int64_t, std::int64_t>{0, 1};
  }
  if (st.is("BitArea")) {
    if (!st.has_args || st.args.size() != 1 || !st.args[0].is_range()) {
      return error(file, st, GsdError::kBadValue, "BitArea expects (first-last)");
    }
    const auto& r = st.args[0];
    if (r.number < 0 || r.high > 7 || r.number > r.high) {
      return error(file, st, GsdError::kOutOfRange,
                   "BitArea(" + std::to_string(r.number) + "-" + std::to_string(r.high) +
                       ") must lie within bits 0..7, first <= last");
    }
    p.type = ParamType::kBitArea;
    p.bit_low = static_cast<int>(r.number);
    p.bit_high = static_cast<int>(r.high);
    return std::pair<std::int64_t, std::int64_t>{
        0, (std::int64_t{1} << (p.bit_high - p.bit_low + 1)) - 1};
  }
  for (const auto& t : kByteTypes) {
    if (st.is(t.keyword)) {
      if (st.has_args) return error(file, st, GsdError::kBadValue, st.keyword + " takes no (…)");
      p.type = t.type;
      return std::pair<std::int64_t, std::int64_t>{t.lo, t.hi};
    }
  }
  return error(file, st, GsdError::kBadValue, "unknown parameter type " + st.keyword);
}

// `<type> default min-max` or `<type> default a,b,c`.
Result<void> read_type_line(const std::string& file, const syntax::Statement& st, ExtParam& p) {
  RS4SIM_GSD_TRY(const auto limits, read_type(file, st, p));
  if (st.has_equals || st.fields.size() != 2 || st.fields[0].size() != 1 ||
      !st.fields[0][0].is_number()) {
    return error(file, st, GsdError::kBadValue,
                 "type line expects: " + st.keyword + " <default> <min-max | a,b,…>");
  }
  p.default_value = st.fields[0][0].number;
  const auto& allowed = st.fields[1];
  if (allowed.size() == 1 && allowed[0].is_range()) {
    p.min = allowed[0].number;
    p.max = allowed[0].high;
    if (p.min > p.max)
      return error(file, st, GsdError::kOutOfRange, "range " + p.range_text() + " is empty");
  } else {
    for (const auto& v : allowed) {
      if (!v.is_number())
        return error(file, st, GsdError::kBadValue, "allowed values must be numbers");
      p.allowed.push_back(v.number);
    }
    p.min = *std::min_element(p.allowed.begin(), p.allowed.end());
    p.max = *std::max_element(p.allowed.begin(), p.allowed.end());
  }
  if (p.min < limits.first || p.max > limits.second) {
    return error(file, st, GsdError::kOutOfRange,
                 "allowed values " + p.range_text() + " do not fit " + st.keyword + " (" +
                     std::to_string(limits.first) + ".." + std::to_string(limits.second) + ")");
  }
  if (!p.accepts(p.default_value)) {
    return error(file, st, GsdError::kOutOfRange,
                 "default " + std::to_string(p.default_value) + " is not within " + p.range_text());
  }
  return boost::outcome_v2::success();
}

}  // namespace

Result<ExtParam> interpret_ext_param(const std::string& file, const syntax::Entry& entry) {
  const syntax::Statement& head = entry.statement;
  ExtParam p;
  p.line = head.line;
  if (!head.has_equals || head.fields.size() != 2 || head.fields[0].size() != 1 ||
      !head.fields[0][0].is_number() || head.fields[1].size() != 1 ||
      !head.fields[1][0].is_string()) {
    return error(file, head, GsdError::kBadValue, "ExtUserPrmData expects = <number> \"name\"");
  }
  const std::int64_t number_value = head.fields[0][0].number;
  if (number_value < 0 || number_value > 65535) {
    return error(
        file, head, GsdError::kOutOfRange,
        "ExtUserPrmData number " + std::to_string(number_value) + " is out of range 0..65535");
  }
  p.number = static_cast<int>(number_value);
  p.name = head.fields[1][0].text;
  bool typed = false;
  for (const auto& st : *entry.body) {
    if (is_type_line(st)) {
      if (typed)
        return error(file, st, GsdError::kDuplicate,
                     "second type line in ExtUserPrmData " + std::to_string(p.number));
      RS4SIM_GSD_TRYV(read_type_line(file, st, p));
      typed = true;
    } else if (st.is("Prm_Text_Ref")) {
      RS4SIM_GSD_TRY(const auto ref, number(file, st, 0, 65535));
      p.prm_text_ref = static_cast<int>(ref);
    } else if (st.is("Changeable")) {
      RS4SIM_GSD_TRY(const auto v, number(file, st, 0, 1));
      p.changeable = v == 1;
    } else if (st.is("Visible")) {
      RS4SIM_GSD_TRY(const auto v, number(file, st, 0, 1));
      p.visible = v == 1;
    }  // other keywords carry nothing a master needs
  }
  if (!typed) {
    return error(file, head, GsdError::kMissingKeyword,
                 "ExtUserPrmData " + std::to_string(p.number) +
                     " has no type line (Bit, BitArea, Unsigned8, …)");
  }
  return p;
}

namespace {

Result<void> read_text(const std::string& file, const syntax::Statement& st, PrmText& t) {
  if (!st.is("Text")) {
    return error(file, st, GsdError::kBadValue, "PrmText holds only Text(value) = \"…\" lines");
  }
  if (!st.has_args || st.args.size() != 1 || !st.args[0].is_number()) {
    return error(file, st, GsdError::kBadValue, "Text expects one number in (…)");
  }
  RS4SIM_GSD_TRY(auto text, string_value(file, st));
  if (!t.texts.emplace(st.args[0].number, std::move(text)).second) {
    return error(file, st, GsdError::kDuplicate,
                 "Text(" + std::to_string(st.args[0].number) + ") given twice");
  }
  return boost::outcome_v2::success();
}

}  // namespace

// The texts only name values: a line that is not one is skipped with a warning.
Result<PrmText> interpret_prm_text(const std::string& file, const syntax::Entry& entry,
                                   std::vector<Warning>& warnings) {
  PrmText t;
  RS4SIM_GSD_TRY(const auto number_value, number(file, entry.statement, 0, 65535));
  t.number = static_cast<int>(number_value);
  for (const auto& st : *entry.body) RS4SIM_GSD_TRYV(forgive(warnings, read_text(file, st, t)));
  return t;
}

}  // namespace rs4sim::gsd::detail
