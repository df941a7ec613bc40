#include "rs4/param_doc/json_tree.h"

#include "json/message.h"
#include "json/path.h"
#include "json/syntax.h"
#include "json/value_kind.h"

#include <google/protobuf/util/json_util.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rs4sim::rs4::param_doc::json {
namespace {

[[noreturn]] void wrong_type(const Value& v, const std::string& path, std::string_view expected) {
  refuse(DocumentError::kWrongType, path,
         "expected " + std::string(expected) + ", found " + rs4sim::json::kind_of(v));
}

std::string number_text(double d) {
  if (std::abs(d) < 1e15 && d == std::floor(d)) {
    return std::to_string(static_cast<std::int64_t>(d));
  }
  char b[32];
  std::snprintf(b, sizeof b, "%g", d);
  return b;
}

bool names_password(std::string_view key) {
  std::string lower(key);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find("password") != std::string::npos;
}

}  // namespace

void refuse(DocumentError e, std::string path, std::string reason) {
  // A path holds the document's keys, of any length: cut, like every value a reason quotes.
  throw Refusal{DocumentIssue{e, rs4sim::json::cut(path), std::move(reason)}};
}

Value parse(std::string_view text) {
  Value root;
  const auto status = rs4sim::json::to_message(text, root, {});
  if (!status.ok()) {
    // Where the grammar breaks, by line and column (the document is edited by hand); what
    // protobuf alone refuses (a duplicate key, a number beyond double) in its own words.
    if (const auto broken = rs4sim::json::first_syntax_error(text)) {
      refuse(DocumentError::kSyntax, "$",
             "not valid JSON at " + rs4sim::json::line_column(text, broken->offset) + ": " +
                 broken->reason);
    }
    refuse(DocumentError::kSyntax, "$", "not valid JSON: " + std::string(status.message()));
  }
  return root;
}

std::string key_path(const std::string& path, std::string_view key) {
  return ::rs4sim::json::member_path(path, key);
}

std::string index_path(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

const Object& object(const Value& v, const std::string& path) {
  if (!v.has_struct_value()) wrong_type(v, path, "an object");
  return v.struct_value();
}

const List& list(const Value& v, const std::string& path) {
  if (!v.has_list_value()) wrong_type(v, path, "an array");
  return v.list_value();
}

const std::string& text(const Value& v, const std::string& path) {
  if (v.kind_case() != Value::kStringValue) wrong_type(v, path, "a string");
  return v.string_value();
}

double number(const Value& v, const std::string& path) {
  if (v.kind_case() != Value::kNumberValue) wrong_type(v, path, "a number");
  const double d = v.number_value();
  if (!std::isfinite(d)) refuse(DocumentError::kOutOfRange, path, "not a finite number");
  return d;
}

std::int64_t integer(const Value& v, const std::string& path, std::int64_t min, std::int64_t max,
                     std::string_view what) {
  const double d = number(v, path);
  if (d != std::floor(d)) {
    refuse(DocumentError::kWrongType, path, number_text(d) + " is not an integer");
  }
  if (d < static_cast<double>(min) || d > static_cast<double>(max)) {
    refuse(DocumentError::kOutOfRange, path,
           number_text(d) + " is outside " + std::to_string(min) + ".." + std::to_string(max) +
               (what.empty() ? "" : " " + std::string(what)));
  }
  return static_cast<std::int64_t>(d);
}

void check_keys(const Object& o, const std::string& path,
                std::initializer_list<std::string_view> allowed) {
  // Sorted, so that the first refused key does not depend on the map's order.
  std::vector<std::string> keys;
  for (const auto& [key, value] : o.fields()) keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  for (const auto& key : keys) {
    if (names_password(key)) {
      refuse(DocumentError::kPasswordInDocument, key_path(path, key),
             "a document never carries passwords; give the password for writing with "
             "--password");
    }
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string known;
    for (const auto name : allowed) known += (known.empty() ? "" : ", ") + std::string(name);
    refuse(DocumentError::kUnknownKey, key_path(path, key),
           "unknown key (allowed here: " + known + ")");
  }
}

const Value* find(const Object& o, std::string_view key) {
  const auto it = o.fields().find(std::string(key));
  return it == o.fields().end() ? nullptr : &it->second;
}

}  // namespace rs4sim::rs4::param_doc::json
