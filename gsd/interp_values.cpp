// Value helpers and the user-parameter template builder ([PROFIBUS GSD spec User_Prm_Data]).
#include "gsd/interp_detail.h"

#include <algorithm>

namespace rs4sim::gsd::detail {

Error error(const std::string& file, const syntax::Statement& st, GsdError code,
            std::string message) {
  return Error{code, file, st.line, st.text, std::move(message)};
}

void warn(std::vector<Warning>& out, const std::string& file, const syntax::Statement& st,
          std::string message) {
  out.push_back({file, st.line, st.text, std::move(message)});
}

Result<void> forgive(std::vector<Warning>& out, Result<void> r) {
  if (r) return r;
  const Error& e = r.error();
  out.push_back({e.file, e.line, e.text, e.message + "; line ignored"});
  return boost::outcome_v2::success();
}

namespace {
std::string range(std::int64_t lo, std::int64_t hi) {
  return std::to_string(lo) + ".." + std::to_string(hi);
}
}  // namespace

Result<std::int64_t> number(const std::string& file, const syntax::Statement& st, std::int64_t lo,
                            std::int64_t hi) {
  if (!st.has_equals || st.fields.size() != 1 || st.fields[0].size() != 1 ||
      !st.fields[0][0].is_number()) {
    return error(file, st, GsdError::kBadValue, st.keyword + " expects one number");
  }
  const std::int64_t v = st.fields[0][0].number;
  if (v < lo || v > hi) {
    return error(file, st, GsdError::kOutOfRange,
                 st.keyword + " = " + std::to_string(v) + " is out of range " + range(lo, hi));
  }
  return v;
}

Result<std::string> string_value(const std::string& file, const syntax::Statement& st) {
  std::string out;
  bool ok = st.has_equals && !st.fields.empty();
  for (const auto& field : st.fields) {
    ok = ok && field.size() == 1 && field[0].is_string();
    if (ok) out += field[0].text;
  }
  if (!ok) return error(file, st, GsdError::kBadValue, st.keyword + " expects a \"string\"");
  return out;
}

Result<std::vector<std::uint8_t>> byte_list(const std::string& file, const syntax::Statement& st,
                                            const syntax::Field& field) {
  std::vector<std::uint8_t> bytes;
  for (const auto& v : field) {
    if (!v.is_number()) {
      return error(file, st, GsdError::kBadValue,
                   st.keyword + ": byte value expected, got '" + v.text + "'");
    }
    if (v.number < 0 || v.number > 255) {
      return error(
          file, st, GsdError::kOutOfRange,
          st.keyword + ": byte value " + std::to_string(v.number) + " is out of range 0..255");
    }
    bytes.push_back(static_cast<std::uint8_t>(v.number));
  }
  return bytes;
}

Result<std::int64_t> number_arg(const std::string& file, const syntax::Statement& st,
                                std::int64_t lo, std::int64_t hi) {
  if (!st.has_args || st.args.size() != 1 || !st.args[0].is_number()) {
    return error(file, st, GsdError::kBadValue, st.keyword + " expects one number in (…)");
  }
  const std::int64_t v = st.args[0].number;
  if (v < lo || v > hi) {
    return error(file, st, GsdError::kOutOfRange,
                 st.keyword + "(" + std::to_string(v) + ") is out of range " + range(lo, hi));
  }
  return v;
}

Result<void> TemplateBuilder::add_const(const std::string& file, const syntax::Statement& st) {
  RS4SIM_GSD_TRY(const auto offset, number_arg(file, st, 0, 243));
  if (!st.has_equals || st.fields.size() != 1) {
    return error(file, st, GsdError::kBadValue, st.keyword + " expects bytes b0,b1,…");
  }
  RS4SIM_GSD_TRY(auto bytes, byte_list(file, st, st.fields[0]));
  consts.push_back({static_cast<std::size_t>(offset), std::move(bytes), &st});
  return boost::outcome_v2::success();
}

Result<void> TemplateBuilder::add_ref(const std::string& file, const syntax::Statement& st) {
  RS4SIM_GSD_TRY(const auto offset, number_arg(file, st, 0, 243));
  RS4SIM_GSD_TRY(const auto param, number(file, st, 0, 65535));
  refs.push_back({static_cast<std::size_t>(offset), static_cast<int>(param), st.line});
  ref_statements.push_back(&st);
  return boost::outcome_v2::success();
}

Result<PrmTemplate> TemplateBuilder::finish(const std::string& file,
                                            const std::map<int, ExtParam>& params,
                                            std::optional<std::size_t> max_length) const {
  PrmTemplate t;
  t.refs = refs;
  // Without a declared length the template is as long as its furthest byte.
  std::size_t extent = 0;
  for (const auto& c : consts) extent = std::max(extent, c.offset + c.bytes.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const auto it = params.find(refs[i].param);
    if (it == params.end()) {
      return error(file, *ref_statements[i], GsdError::kUnknownReference,
                   what + ": no ExtUserPrmData " + std::to_string(refs[i].param));
    }
    extent = std::max(extent, refs[i].offset + byte_size(it->second.type));
  }
  t.length = length.value_or(extent);
  if (max_length && t.length > *max_length) {
    const syntax::Statement* at =
        length_st ? length_st : (consts.empty() ? ref_statements.front() : consts.front().st);
    return error(file, *at, GsdError::kPrmTooLong,
                 what + " is " + std::to_string(t.length) + " bytes, more than the maximum " +
                     std::to_string(*max_length));
  }
  for (const auto& c : consts) {
    if (c.offset + c.bytes.size() > t.length) {
      return error(file, *c.st, GsdError::kOutOfRange,
                   what + ": constant bytes end at byte " +
                       std::to_string(c.offset + c.bytes.size()) + ", beyond the length " +
                       std::to_string(t.length));
    }
  }
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const std::size_t end = refs[i].offset + byte_size(params.at(refs[i].param).type);
    if (end > t.length) {
      return error(file, *ref_statements[i], GsdError::kOutOfRange,
                   what + ": parameter ends at byte " + std::to_string(end) +
                       ", beyond the length " + std::to_string(t.length));
    }
  }
  t.defaults.assign(t.length, 0);
  for (const auto& c : consts)
    std::copy(c.bytes.begin(), c.bytes.end(),
              t.defaults.begin() + static_cast<std::ptrdiff_t>(c.offset));
  return t;
}

}  // namespace rs4sim::gsd::detail
