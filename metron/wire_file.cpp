// The wire-table file (wire_file.h). JSON is read with protobuf's JSON parser into a
// google.protobuf.Value, as the bus file and the parameter documents are: Debian 12's Boost
// (1.74) has no Boost.JSON and the project links protobuf anyway (docs/decisions.md
// "metron-wire-table-file").
#include "metron/wire_file.h"

#include "json/message.h"
#include "json/path.h"
#include "json/syntax.h"
#include "json/value_kind.h"

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace rs4sim::metron {
namespace {

using google::protobuf::Value;

// Thrown inside the reader, caught by apply_wire_json.
struct Refusal {
  WireFileIssue issue;
};

[[noreturn]] void refuse(std::string where, std::string reason) {
  throw Refusal{{std::move(where), std::move(reason), false}};
}

using json::kind_of;

// An object's members in key order: the first issue reported does not depend on the map's
// order.
std::vector<std::pair<std::string, const Value*>> members(const Value& v) {
  std::vector<std::pair<std::string, const Value*>> out;
  for (const auto& [key, value] : v.struct_value().fields()) out.emplace_back(key, &value);
  std::sort(out.begin(), out.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

// A member of an object with its path (`at`) below the object's.
struct Member {
  std::string key;
  const Value& value;
  std::string at;
};

// The members of the object `v` in key order, with their paths below `where`; a value that
// is not an object is refused at `where`.
std::vector<Member> members_of(const Value& v, const std::string& where) {
  if (!v.has_struct_value()) refuse(where, "expected an object, found " + kind_of(v));
  std::vector<Member> out;
  for (const auto& [key, value] : members(v))
    out.push_back(Member{key, *value, json::member_path(where, key)});
  return out;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::uint8_t byte_of(const Value& v, const std::string& where) {
  if (v.kind_case() == Value::kNumberValue) {
    const double d = v.number_value();
    if (d != std::floor(d) || d < 0 || d > 255) {
      char b[64];
      std::snprintf(b, sizeof b, "%g is not a byte (0..255 or \"0x00\"..\"0xFF\")", d);
      refuse(where, b);
    }
    return static_cast<std::uint8_t>(d);
  }
  if (v.kind_case() == Value::kStringValue) {
    const std::string& s = v.string_value();
    const bool prefix = s.size() >= 3 && s.size() <= 4 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    int value = 0;
    for (std::size_t i = 2; prefix && i < s.size(); ++i) {
      const int d = hex_digit(s[i]);
      if (d < 0) break;
      value = value * 16 + d;
      if (i + 1 == s.size()) return static_cast<std::uint8_t>(value);
    }
    refuse(where, "\"" + json::cut(s) + "\" is not a byte (0..255 or \"0x00\"..\"0xFF\")");
  }
  refuse(where, "expected a byte (0..255 or \"0x00\"..\"0xFF\"), found " + kind_of(v));
}

const google::protobuf::ListValue& list_of(const Value& v, const std::string& where) {
  if (!v.has_list_value()) refuse(where, "expected an array, found " + kind_of(v));
  return v.list_value();
}

const std::string& text_of(const Value& v, const std::string& where) {
  if (v.kind_case() != Value::kStringValue) refuse(where, "expected a string, found " + kind_of(v));
  return v.string_value();
}

template <std::size_t N>
void read_bytes(const Value& v, const std::string& where, std::array<std::uint8_t, N>& out,
                std::string_view what) {
  const auto& l = list_of(v, where);
  if (static_cast<std::size_t>(l.values_size()) != N) {
    refuse(where, "expected " + std::to_string(N) + " bytes (" + std::string(what) + "), found " +
                      std::to_string(l.values_size()));
  }
  for (std::size_t i = 0; i < N; ++i)
    out[i] = byte_of(l.values(static_cast<int>(i)), where + "[" + std::to_string(i) + "]");
}

ReplyField reply_field(const Value& v, const std::string& where) {
  const auto& t = text_of(v, where);
  const auto f = parse_reply_field(t);
  if (!f) {
    refuse(where, "no reply field \"" + t +
                      "\" (fields: start, node, length, code, data, checksum)");
  }
  return *f;
}

ReplyFieldSet reply_field_set(const Value& v, const std::string& where) {
  const auto& l = list_of(v, where);
  ReplyFieldSet set = 0;
  for (int i = 0; i < l.values_size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    const auto f = reply_field(l.values(i), at);
    if (contains(set, f)) refuse(at, "\"" + std::string(to_token(f)) + "\" is listed twice");
    set = static_cast<ReplyFieldSet>(set | field_bit(f));
  }
  return set;
}

void read_reply(const Value& v, ReplyLayout& r) {
  for (const auto& [key, value, where] : members_of(v, "reply")) {
    if (key == "fields") {
      const auto& l = list_of(value, where);
      r.fields.clear();
      for (int i = 0; i < l.values_size(); ++i)
        r.fields.push_back(reply_field(l.values(i), where + "[" + std::to_string(i) + "]"));
    } else if (key == "length_counts") {
      r.length_counts = reply_field_set(value, where);
    } else if (key == "checksum_covers") {
      r.checksum_covers = reply_field_set(value, where);
    } else {
      refuse(where, "unknown key (reply takes: fields, length_counts, checksum_covers)");
    }
  }
}

void read_report(const Value& v, ReportLayout& r) {
  for (const auto& [key, value, where] : members_of(v, "report")) {
    if (key == "order") {
      const auto& l = list_of(value, where);
      if (l.values_size() != static_cast<int>(kReportFieldCount)) {
        refuse(where, "expected 4 parts (start, data, checksum, end in some order), found " +
                          std::to_string(l.values_size()));
      }
      for (int i = 0; i < l.values_size(); ++i) {
        const std::string at = where + "[" + std::to_string(i) + "]";
        const auto& t = text_of(l.values(i), at);
        const auto f = parse_report_field(t);
        if (!f) refuse(at, "no report part \"" + t + "\" (parts: start, data, checksum, end)");
        r.order[static_cast<std::size_t>(i)] = *f;
      }
    } else if (key == "checksum_over") {
      const auto& t = text_of(value, where);
      if (t != "values" && t != "characters")
        refuse(where, "\"" + json::cut(t) + "\": expected \"values\" or \"characters\"");
      r.checksum_over_characters = t == "characters";
    } else {
      refuse(where, "unknown key (report takes: order, checksum_over)");
    }
  }
}

// A list of tokens of one kind, each once (`parse` names them, `known` lists them for the
// message).
template <class E>
std::vector<E> read_tokens(const Value& v, const std::string& where,
                           std::optional<E> (*parse)(std::string_view), std::string_view known) {
  const auto& l = list_of(v, where);
  std::vector<E> out;
  for (int i = 0; i < l.values_size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    const auto& t = text_of(l.values(i), at);
    const auto item = parse(t);
    if (!item) refuse(at, "no item \"" + t + "\" (items: " + std::string(known) + ")");
    out.push_back(*item);
  }
  return out;
}

void read_curtain_status(const Value& v, const std::string& where,
                         std::array<std::uint8_t, kStatusFlagCount>& masks) {
  for (const auto& [key, value, at] : members_of(v, where)) {
    const auto flag = parse_status_flag(key);
    if (!flag) {
      refuse(at, "unknown flag (flags: synchronised, ossd_enabled, ossd_standby, "
                 "ossd_measuring, measuring, interrupted, input_high)");
    }
    masks[static_cast<std::size_t>(*flag)] = byte_of(value, at);
  }
}

void read_replies(const Value& v, ReplyData& r) {
  for (const auto& [key, value, where] : members_of(v, "replies")) {
    if (key == "stop_measurement") {
      r.stop_measurement = read_tokens<StopItem>(value, where, parse_stop_item, "code, maximum");
    } else if (key == "beam_interrupted") {
      r.beam_interrupted = byte_of(value, where);
    } else if (key == "beam_free") {
      r.beam_free = byte_of(value, where);
    } else if (key == "configuration") {
      r.configuration = read_tokens<ConfigItem>(value, where, parse_config_item,
                                                "beams, input_type, node, scan_cycle, t_response");
    } else if (key == "curtain_status") {
      read_curtain_status(value, where, r.curtain_status);
    } else {
      refuse(where, "unknown key (replies takes: stop_measurement, beam_interrupted, beam_free, "
                    "configuration, curtain_status)");
    }
  }
}

void read_table(const Value& root, WireTable& t) {
  if (!root.has_struct_value()) refuse("$", "expected an object {\"commands\": [...], ...}");
  for (const auto& [key, member] : members(root)) {
    const Value& v = *member;
    if (key == "frame_start") t.frame_start = byte_of(v, key);
    else if (key == "commands") read_bytes(v, key, t.commands, "#1..#13 in the manual's order");
    else if (key == "errors") read_bytes(v, key, t.errors, "E1..E5");
    else if (key == "measurements")
      read_bytes(v, key, t.measurements, "first, last, count, free, central, run");
    else if (key == "all_beams") t.all_beams = byte_of(v, key);
    else if (key == "beam_bits") {
      const auto& s = text_of(v, key);
      if (s != "lsb-first" && s != "msb-first")
        refuse(key, "\"" + json::cut(s) + "\": expected \"lsb-first\" or \"msb-first\"");
      t.beam_bits_lsb_first = s == "lsb-first";
    } else if (key == "report_start") t.report_start = byte_of(v, key);
    else if (key == "report_end") t.report_end = byte_of(v, key);
    else if (key == "separator") t.separator = byte_of(v, key);
    else if (key == "request_char") t.request_char = byte_of(v, key);
    else if (key == "reply") read_reply(v, t.reply);
    else if (key == "report") read_report(v, t.report);
    else if (key == "replies") read_replies(v, t.replies);
    else {
      refuse(json::member_path("", key),
             "unknown key (the wire table takes: frame_start, commands, errors, measurements, "
             "all_beams, beam_bits, report_start, report_end, separator, request_char, reply, "
             "report, replies)");
    }
  }
}

// A text protobuf's parser refuses: the first break of the grammar with its line:column, or,
// where the text is JSON that protobuf still refuses (a number beyond double, a duplicate
// key), protobuf's own message without a position.
WireFileIssue syntax_issue(std::string_view text, std::string_view message) {
  if (const auto syntax = json::first_syntax_error(text))
    return {json::line_column(text, syntax->offset), "not valid JSON: " + syntax->reason, true};
  return {"", "not valid JSON: " + std::string(message), true};
}

std::string byte_text(std::uint8_t b) {
  char s[8];
  std::snprintf(s, sizeof s, "\"0x%02X\"", b);
  return s;
}

template <std::size_t N>
std::string bytes_text(const std::array<std::uint8_t, N>& a) {
  std::string s = "[";
  for (std::size_t i = 0; i < N; ++i) s += (i ? ", " : "") + byte_text(a[i]);
  return s + "]";
}

std::string set_text(ReplyFieldSet set) {
  std::string s = "[";
  for (std::size_t i = 0; i < kReplyFieldCount; ++i) {
    const auto f = static_cast<ReplyField>(i);
    if (contains(set, f)) s += (s.size() > 1 ? ", \"" : "\"") + std::string(to_token(f)) + "\"";
  }
  return s + "]";
}

template <class E>
std::string tokens_text(const std::vector<E>& items) {
  std::string s = "[";
  for (std::size_t i = 0; i < items.size(); ++i)
    s += (i ? ", \"" : "\"") + std::string(to_token(items[i])) + "\"";
  return s + "]";
}

std::string replies_text(const ReplyData& r) {
  std::string s = "  \"replies\": {\n";
  s += "    \"stop_measurement\": " + tokens_text(r.stop_measurement) + ",\n";
  s += "    \"beam_interrupted\": " + byte_text(r.beam_interrupted) + ",\n";
  s += "    \"beam_free\": " + byte_text(r.beam_free) + ",\n";
  s += "    \"configuration\": " + tokens_text(r.configuration) + ",\n";
  s += "    \"curtain_status\": {";
  for (std::size_t i = 0; i < kStatusFlagCount; ++i) {
    s += std::string(i ? ", \"" : "\"") + std::string(to_token(static_cast<StatusFlag>(i))) +
         "\": " + byte_text(r.curtain_status[i]);
  }
  return s + "}\n  }";
}

}  // namespace

std::optional<WireFileIssue> apply_wire_json(std::string_view text, WireTable& table) {
  Value root;
  const auto status = json::to_message(text, root, {});
  if (!status.ok()) return syntax_issue(text, std::string(status.message()));
  try {
    read_table(root, table);
  } catch (const Refusal& r) {
    return r.issue;
  }
  if (auto issue = check(table)) return WireFileIssue{issue->key, issue->reason, false};
  return std::nullopt;
}

std::string wire_json(const WireTable& t) {
  std::string s = "{\n";
  s += "  \"frame_start\": " + byte_text(t.frame_start) + ",\n";
  s += "  \"commands\": " + bytes_text(t.commands) + ",\n";
  s += "  \"errors\": " + bytes_text(t.errors) + ",\n";
  s += "  \"all_beams\": " + byte_text(t.all_beams) + ",\n";
  s += std::string("  \"beam_bits\": \"") + (t.beam_bits_lsb_first ? "lsb-first" : "msb-first") +
       "\",\n";
  s += "  \"measurements\": " + bytes_text(t.measurements) + ",\n";
  s += "  \"report_start\": " + byte_text(t.report_start) + ",\n";
  s += "  \"report_end\": " + byte_text(t.report_end) + ",\n";
  s += "  \"separator\": " + byte_text(t.separator) + ",\n";
  s += "  \"request_char\": " + byte_text(t.request_char) + ",\n";
  s += "  \"reply\": {\n    \"fields\": [";
  for (std::size_t i = 0; i < t.reply.fields.size(); ++i)
    s += (i ? ", \"" : "\"") + std::string(to_token(t.reply.fields[i])) + "\"";
  s += "],\n    \"length_counts\": " + set_text(t.reply.length_counts) + ",\n";
  s += "    \"checksum_covers\": " + set_text(t.reply.checksum_covers) + "\n  },\n";
  s += "  \"report\": {\n    \"order\": [";
  for (std::size_t i = 0; i < kReportFieldCount; ++i)
    s += (i ? ", \"" : "\"") + std::string(to_token(t.report.order[i])) + "\"";
  s += std::string("],\n    \"checksum_over\": \"") +
       (t.report.checksum_over_characters ? "characters" : "values") + "\"\n  },\n";
  return s + replies_text(t.replies) + "\n}\n";
}

}  // namespace rs4sim::metron
