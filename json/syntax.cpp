// The JSON grammar scanner (syntax.h). Moved from app/devices/bus_file.cpp, unchanged in what
// it accepts and where it stops.
#include "json/syntax.h"

#include <algorithm>
#include <cctype>

namespace rs4sim::json {
namespace {

// A recursive-descent walk over RFC 8259's grammar that keeps the first failure.
class JsonScanner {
 public:
  explicit JsonScanner(std::string_view text) : t_(text) {}
  std::optional<SyntaxError> check() {
    space();
    if (!value(0)) return error_;
    space();
    if (i_ < t_.size()) return SyntaxError{i_, "text after the end of the JSON value"};
    return std::nullopt;
  }

 private:
  static constexpr int kMaxDepth = 100;  // protobuf's recursion limit

  bool close() {  // the bracket that ends an object or array
    ++i_;
    return true;
  }
  bool fail(const std::string& reason) {
    error_ = {i_, reason};
    return false;
  }
  void space() {
    while (i_ < t_.size() &&
           (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r')) {
      ++i_;
    }
  }
  bool literal(std::string_view word) {
    if (t_.substr(i_, word.size()) != word) return fail("expected a value");
    i_ += word.size();
    return true;
  }
  bool digits() {
    const std::size_t start = i_;
    while (i_ < t_.size() && t_[i_] >= '0' && t_[i_] <= '9') ++i_;
    return i_ > start || fail("expected a digit");
  }
  bool number() {
    if (t_[i_] == '-') ++i_;
    if (i_ < t_.size() && t_[i_] == '0') {
      ++i_;
    } else if (!digits()) {
      return false;
    }
    if (i_ < t_.size() && t_[i_] == '.') {
      ++i_;
      if (!digits()) return false;
    }
    if (i_ < t_.size() && (t_[i_] == 'e' || t_[i_] == 'E')) {
      ++i_;
      if (i_ < t_.size() && (t_[i_] == '+' || t_[i_] == '-')) ++i_;
      if (!digits()) return false;
    }
    return true;
  }
  bool string() {
    const std::size_t start = i_;
    ++i_;  // the opening quote
    while (i_ < t_.size() && t_[i_] != '"') {
      const auto c = static_cast<unsigned char>(t_[i_]);
      if (c < 0x20) return fail("a control character in a string (write it escaped)");
      if (c == '\\') {
        ++i_;
        if (i_ >= t_.size()) break;
        if (t_[i_] == 'u') {
          for (std::size_t k = 1; k <= 4; ++k) {
            if (i_ + k >= t_.size() || !std::isxdigit(static_cast<unsigned char>(t_[i_ + k]))) {
              return fail("expected four hex digits after \\u");
            }
          }
          i_ += 4;
        } else if (std::string_view("\"\\/bfnrt").find(t_[i_]) == std::string_view::npos) {
          return fail("an unknown escape in a string");
        }
      }
      ++i_;
    }
    if (i_ >= t_.size()) {
      i_ = start;  // where the string began
      return fail("a string without its closing quote");
    }
    ++i_;
    return true;
  }
  bool value(int depth) {
    if (depth > kMaxDepth) return fail("nested deeper than 100");
    if (i_ >= t_.size()) return fail("expected a value, found the end of the text");
    switch (t_[i_]) {
      case '{': return object(depth);
      case '[': return array(depth);
      case '"': return string();
      case 't': return literal("true");
      case 'f': return literal("false");
      case 'n': return literal("null");
      default:
        if (t_[i_] == '-' || (t_[i_] >= '0' && t_[i_] <= '9')) return number();
        return fail("expected a value");
    }
  }
  bool object(int depth) {
    ++i_;
    space();
    if (i_ < t_.size() && t_[i_] == '}') return close();
    for (;;) {
      space();
      if (i_ >= t_.size() || t_[i_] != '"') return fail("expected a key in double quotes");
      if (!string()) return false;
      space();
      if (i_ >= t_.size() || t_[i_] != ':') return fail("expected ':' after the key");
      ++i_;
      space();
      if (!value(depth + 1)) return false;
      if (const Next n = next('}'); n != Next::kItem) return n == Next::kEnd && close();
    }
  }
  bool array(int depth) {
    ++i_;
    space();
    if (i_ < t_.size() && t_[i_] == ']') return close();
    for (;;) {
      space();
      if (!value(depth + 1)) return false;
      if (const Next n = next(']'); n != Next::kItem) return n == Next::kEnd && close();
    }
  }
  // After an object member or an array element: another item (past its ','), the end (at
  // the closing bracket, not consumed yet), or a break (recorded).
  enum class Next { kItem, kEnd, kBroken };
  Next next(char closing) {
    space();
    if (i_ < t_.size() && t_[i_] == ',') {
      ++i_;
      return Next::kItem;
    }
    if (i_ < t_.size() && t_[i_] == closing) return Next::kEnd;
    fail(closing == '}' ? "expected ',' or '}' after an object member"
                        : "expected ',' or ']' after an array element");
    return Next::kBroken;
  }

  std::string_view t_;
  std::size_t i_ = 0;
  SyntaxError error_;
};

}  // namespace

std::optional<SyntaxError> first_syntax_error(std::string_view text) {
  return JsonScanner(text).check();
}

std::string line_column(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const auto before = text.substr(0, offset);
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const auto nl = before.rfind('\n');
  const auto column = nl == std::string_view::npos ? offset + 1 : offset - nl;
  return std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace rs4sim::json
