#pragma once
// A small streaming JSON writer: deterministic output (keys in the order written, integers
// only, fixed indentation), RFC 8259 string escaping. Used for the decoded summary the
// archive stores, the diff's JSON and the CLI's --json documents.

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace rs4sim::rs4::report {

// `text` as a JSON string literal, quotes included (json::string_literal).
std::string json_quote(std::string_view text);

class JsonWriter {
 public:
  // indent 0: one line, no spaces; otherwise pretty-printed with that many spaces a level.
  explicit JsonWriter(int indent = 0) : indent_(indent) {}

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  JsonWriter& key(std::string_view name);
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(const std::string& text) { return value(std::string_view(text)); }
  JsonWriter& value(std::int64_t number);
  JsonWriter& value(bool flag);
  JsonWriter& null();
  // An already serialised JSON value, inserted as is (one line).
  JsonWriter& raw(std::string_view json);

  // key(name).value(v) in one call.
  template <class T>
  JsonWriter& field(std::string_view name, const T& v) {
    key(name);
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
      return value(static_cast<std::int64_t>(v));
    } else {
      return value(v);
    }
  }

  [[nodiscard]] const std::string& str() const { return out_; }

 private:
  void before_value();
  void newline();
  JsonWriter& close(char bracket);

  int indent_;
  std::string out_;
  std::vector<bool> first_;  // per open container: nothing written in it yet
  bool after_key_ = false;
};

}  // namespace rs4sim::rs4::report
