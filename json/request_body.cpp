// normalise_body (request_body.h): parse once into google.protobuf.Value (structure checked),
// walk it beside the message's descriptor, collect the string values to replace by their
// member path, and replace them in the text (numbers and everything else keep their spelling:
// a Value holds numbers as doubles).
#include "json/request_body.h"

#include "json/locate.h"
#include "json/message.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/struct.pb.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <utility>
#include <vector>

namespace rs4sim::json {
namespace {

namespace pb = google::protobuf;

std::string upper_name(std::string_view text) {
  std::string out;
  for (const char c : text) {
    out += (c == '-' || c == ' ') ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

// The prefix every value name of the enum shares, up to its last '_' ("FIELD_KIND_").
std::string enum_prefix(const pb::EnumDescriptor& e) {
  std::string prefix = e.value(0)->name();
  for (int i = 1; i < e.value_count(); ++i) {
    const std::string& name = e.value(i)->name();
    std::size_t n = 0;
    while (n < prefix.size() && n < name.size() && prefix[n] == name[n]) ++n;
    prefix.resize(n);
  }
  const auto cut = prefix.rfind('_');
  return cut == std::string::npos || e.value_count() < 2 ? "" : prefix.substr(0, cut + 1);
}

std::string enum_names(const pb::EnumDescriptor& e, const std::string& prefix) {
  std::string out;
  for (int i = 0; i < e.value_count(); ++i) {
    out += (i ? ", " : "") + e.value(i)->name().substr(prefix.size());
  }
  return out;
}

std::string field_names(const pb::Descriptor& d) {
  std::string out;
  for (int i = 0; i < d.field_count(); ++i) {
    const pb::FieldDescriptor& f = *d.field(i);
    out += (i ? ", " : "") + f.name();
    if (f.json_name() != f.name()) out += " (" + f.json_name() + ")";
  }
  return out.empty() ? "none" : out;
}

// A member by the field's name or its JSON name, as protobuf's parser accepts both.
const pb::FieldDescriptor* find_field(const pb::Descriptor& d, const std::string& key) {
  if (const auto* f = d.FindFieldByName(key)) return f;
  for (int i = 0; i < d.field_count(); ++i) {
    if (d.field(i)->json_name() == key) return d.field(i);
  }
  return nullptr;
}

constexpr char kBase64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64(std::string_view bytes) {
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    unsigned v = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      v = (v << 8U) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0U);
    }
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kBase64[(v >> (18 - 6 * k)) & 0x3FU] : '=';
  }
  return out;
}

// The bytes base64 gives `text` (all hex digits here, so all in its alphabet), as hex pairs,
// the first 8; how protobuf would have read it.
std::string base64_reading(std::string_view text) {
  std::string out;
  unsigned acc = 0, n = 0, count = 0;
  for (const char c : text) {
    acc = (acc << 6U) | static_cast<unsigned>(std::string_view(kBase64).find(c));
    n += 6;
    if (n >= 8) {
      n -= 8;
      ++count;
      static constexpr char kHex[] = "0123456789abcdef";
      const unsigned byte = (acc >> n) & 0xFFU;
      if (count <= 8) out += std::string(count > 1 ? " " : "") + kHex[byte >> 4U] + kHex[byte & 15U];
    }
  }
  return std::to_string(count) + " bytes " + out + (count > 8 ? " …" : "");
}

bool all_hex(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
  });
}

std::string spaced(std::string_view hex) {
  std::string out;
  for (std::size_t i = 0; i < hex.size(); i += 2) out += (i ? " " : "") + std::string(hex.substr(i, 2));
  return out;
}

class Walker {
 public:
  std::vector<std::pair<std::string, std::string>> edits;  // path, new string value
  std::optional<BodyRefusal> refusal;

  void message(const pb::Value& v, const pb::Descriptor& d, const std::string& path) {
    if (d.file()->name().rfind("google/protobuf/", 0) == 0) return;  // well-known: their own JSON
    if (v.kind_case() != pb::Value::kStructValue) return;          // protobuf says what is wrong
    for (const auto& [key, member] : v.struct_value().fields()) {
      const pb::FieldDescriptor* f = find_field(d, key);
      // A key a member path cannot name ('.', '[') is left to protobuf as it is.
      if (key.find_first_of(".[]") != std::string::npos) continue;
      const std::string at = path.empty() ? key : path + "." + key;
      if (f == nullptr) {
        refuse(at, "unknown field '" + key + "' in " + d.full_name() + "; its fields: " +
                       field_names(d));
        return;
      }
      field(member, *f, at);
      if (refusal) return;
    }
  }

 private:
  void refuse(const std::string& at, std::string reason) {
    if (!refusal) refusal = BodyRefusal{at, std::move(reason)};
  }

  void field(const pb::Value& v, const pb::FieldDescriptor& f, const std::string& at) {
    if (f.is_map()) {
      if (v.kind_case() != pb::Value::kStructValue) return;
      for (const auto& [key, entry] : v.struct_value().fields()) {
        if (key.find_first_of(".[]") == std::string::npos) {
          one(entry, *f.message_type()->map_value(), at + "." + key);
        }
      }
    } else if (f.is_repeated() && v.kind_case() == pb::Value::kListValue) {
      for (int i = 0; i < v.list_value().values_size(); ++i) {
        one(v.list_value().values(i), f, at + "[" + std::to_string(i) + "]");
      }
    } else {
      one(v, f, at);
    }
  }

  void one(const pb::Value& v, const pb::FieldDescriptor& f, const std::string& at) {
    if (f.type() == pb::FieldDescriptor::TYPE_MESSAGE) {
      message(v, *f.message_type(), at);
    } else if (v.kind_case() == pb::Value::kStringValue && f.type() == pb::FieldDescriptor::TYPE_ENUM) {
      enum_value(v.string_value(), *f.enum_type(), at);
    } else if (v.kind_case() == pb::Value::kStringValue && f.type() == pb::FieldDescriptor::TYPE_BYTES) {
      bytes_value(v.string_value(), at);
    }
  }

  void enum_value(const std::string& text, const pb::EnumDescriptor& e, const std::string& at) {
    if (e.FindValueByName(text) != nullptr || e.full_name() == "google.protobuf.NullValue") return;
    if (!text.empty() && text.find_first_not_of("0123456789-") == std::string::npos) return;
    const std::string prefix = enum_prefix(e);
    const std::string name = upper_name(text);
    if (e.FindValueByName(name) != nullptr) {
      edits.emplace_back(at, name);
    } else if (!prefix.empty() && e.FindValueByName(prefix + name) != nullptr) {
      edits.emplace_back(at, prefix + name);
    } else {
      refuse(at, "'" + cut(text) + "' is not a " + e.full_name() + ": " + enum_names(e, prefix) +
                     (prefix.empty() ? "" : " (each also as " + prefix + "NAME)"));
    }
  }

  void bytes_value(const std::string& text, const std::string& at) {
    const bool tagged = text.size() >= 4 && upper_name(text.substr(0, 4)) == "HEX:";
    const std::string_view hex = tagged ? std::string_view(text).substr(4) : std::string_view(text);
    if (tagged || (text.find_first_of(" :") != std::string::npos && hex.find_first_not_of(
                                                                         "0123456789abcdefABCDEF :") ==
                                                                         std::string::npos)) {
      const auto bytes = hex_bytes(hex);
      if (!bytes) {
        refuse(at, "'" + cut(text) + "' is not hex bytes: pairs of hex digits, each optionally "
                                     "followed by a space or a colon");
        return;
      }
      edits.emplace_back(at, base64(*bytes));
    } else if (all_hex(text) && text.size() % 2 == 0) {
      refuse(at, "'" + cut(text) + "' reads as hex (" + std::to_string(text.size() / 2) +
                     " bytes) and as base64, protobuf's JSON for bytes (" + base64_reading(text) +
                     "): write hex as 'hex:" + cut(text) + "' or '" + cut(spaced(text)) +
                     "', base64 with its '=' padding where it has one");
    }
  }
};

// The string token at `offset` (its opening quote) replaced by "value".
void replace_string(std::string& text, std::size_t offset, const std::string& value) {
  std::size_t end = offset + 1;
  while (end < text.size() && text[end] != '"') end += text[end] == '\\' ? 2U : 1U;
  text.replace(offset, std::min(end + 1, text.size()) - offset, "\"" + value + "\"");
}

}  // namespace

std::optional<std::string> hex_bytes(std::string_view text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (i + 1 >= text.size() || !all_hex(text.substr(i, 2))) return std::nullopt;
    out += static_cast<char>(std::stoi(std::string(text.substr(i, 2)), nullptr, 16));
    i += 2;
    if (i < text.size() && (text[i] == ' ' || text[i] == ':')) {
      if (++i == text.size()) return std::nullopt;  // a separator at the end
    }
  }
  if (out.empty()) return std::nullopt;
  return out;
}

std::optional<BodyRefusal> normalise_body(std::string& text, const pb::Descriptor& type) {
  pb::Value value;
  if (!to_message(text, value, pb::util::JsonParseOptions{}).ok()) return std::nullopt;
  Walker walker;
  walker.message(value, type, "");
  if (walker.refusal) return walker.refusal;
  std::vector<std::pair<std::size_t, std::string>> at;
  for (const auto& [path, replacement] : walker.edits) {
    if (const auto offset = offset_of_member(text, path)) at.emplace_back(*offset, replacement);
  }
  std::sort(at.begin(), at.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [offset, replacement] : at) {
    if (text[offset] == '"') replace_string(text, offset, replacement);
  }
  return std::nullopt;
}

}  // namespace rs4sim::json
