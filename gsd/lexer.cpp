// GSD lexer: physical lines → logical lines → tokens → one Statement per logical line.
// Grammar ([PROFIBUS GSD spec syntax]): `;` starts a comment (outside strings), `\` at the end
// of a line continues it, strings are "…", numbers are decimal or 0x-hex, keywords
// may start with digits (`9.6_supp`, `MaxTsdr_1.5M`).
#include "gsd/syntax.h"

#include <cctype>
#include <cstdio>
#include <limits>

namespace rs4sim::gsd::syntax {
namespace {

constexpr std::int64_t kMaxNumber = std::numeric_limits<std::uint32_t>::max();
constexpr std::size_t kMaxLogicalLine = 64 * 1024;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool is_word(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '@';
}

Error error_at(const std::string& file, int line, std::string text, std::string message) {
  return Error{GsdError::kSyntax, file, line, std::move(text), std::move(message)};
}

// Removes a `;` comment (outside strings) and trailing blanks from one physical line.
std::string_view strip_comment(std::string_view line) {
  bool in_string = false;
  std::size_t end = line.size();
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') in_string = !in_string;
    if (line[i] == ';' && !in_string) {
      end = i;
      break;
    }
  }
  line = line.substr(0, end);
  while (!line.empty() && is_space(line.back())) line.remove_suffix(1);
  return line;
}

struct Token {
  enum class Kind { kWord, kString, kPunct };
  Kind kind = Kind::kWord;
  std::string text;
  bool space_before = false;
};

Result<std::vector<Token>> tokenize(const LogicalLine& line, const std::string& file) {
  std::vector<Token> tokens;
  const std::string& s = line.text;
  bool space = false;
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (is_space(c)) {
      space = true;
      ++i;
    } else if (c == '"') {
      const std::size_t close = s.find('"', i + 1);
      if (close == std::string::npos) {
        return error_at(file, line.line, s.substr(i), "unterminated string");
      }
      tokens.push_back({Token::Kind::kString, s.substr(i + 1, close - i - 1), space});
      i = close + 1;
      space = false;
    } else if (is_word(c)) {
      // A name with `@` is a main family with sub-families, `Slave_Family = 2@Motor
      // starter@Direct soft starter` ([PROFIBUS GSD spec Slave_Family]): after the first `@`
      // the name runs to the end of the line (trailing blanks dropped), so blanks, `-` and `/`
      // are part of the sub-family names.
      std::size_t j = i;
      while (j < s.size() && is_word(s[j]) && s[j] != '@') ++j;
      if (j < s.size() && s[j] == '@') {
        j = s.size();
        while (j > i && is_space(s[j - 1])) --j;
      }
      tokens.push_back({Token::Kind::kWord, s.substr(i, j - i), space});
      i = j;
      space = false;
    } else if (c == '=' || c == '(' || c == ')' || c == ',' || c == '-' || c == '#') {
      tokens.push_back({Token::Kind::kPunct, std::string(1, c), space});
      ++i;
      space = false;
    } else {
      const auto byte = static_cast<unsigned char>(c);
      char shown[48];
      std::snprintf(shown, sizeof shown,
                    std::isprint(byte) ? "unexpected character '%c'" : "unexpected byte 0x%02X",
                    byte);
      return error_at(file, line.line, s, shown);
    }
  }
  return tokens;
}

// Decimal or 0x-hex; nullopt = not a number (a name such as `9.6_supp`).
Result<std::optional<std::int64_t>> to_number(const std::string& word, const std::string& file,
                                              const LogicalLine& line) {
  const bool hex = word.size() >= 2 && word[0] == '0' && (word[1] == 'x' || word[1] == 'X');
  const std::size_t start = hex ? 2 : 0;
  const int base = hex ? 16 : 10;
  if (start == word.size()) return error_at(file, line.line, word, "malformed hex number");
  std::int64_t value = 0;
  for (std::size_t i = start; i < word.size(); ++i) {
    const auto ch = static_cast<unsigned char>(word[i]);
    const bool digit = hex ? std::isxdigit(ch) != 0 : std::isdigit(ch) != 0;
    if (!digit) {
      if (hex) return error_at(file, line.line, word, "malformed hex number");
      return std::optional<std::int64_t>{};
    }
    const int d = std::isdigit(ch) ? ch - '0' : (std::tolower(ch) - 'a' + 10);
    value = value * base + d;
    if (value > kMaxNumber) return error_at(file, line.line, word, "number too large");
  }
  return std::optional<std::int64_t>{value};
}

class StatementParser {
 public:
  StatementParser(const LogicalLine& line, const std::string& file, std::vector<Token> tokens)
      : line_(line), file_(file), t_(std::move(tokens)) {}

  Result<Statement> run();

 private:
  bool at(std::string_view punct) const {
    return i_ < t_.size() && t_[i_].kind == Token::Kind::kPunct && t_[i_].text == punct;
  }
  Error fail(std::string message) const {
    const std::string near = i_ < t_.size() ? t_[i_].text : std::string("end of line");
    return error_at(file_, line_.line, line_.text, std::move(message) + " near '" + near + "'");
  }
  Result<std::int64_t> signed_number();
  Result<Value> item();
  Result<std::vector<Value>> comma_list();

  const LogicalLine& line_;
  const std::string& file_;
  std::vector<Token> t_;
  std::size_t i_ = 0;
};

Result<std::int64_t> StatementParser::signed_number() {
  bool negative = false;
  if (at("-")) {
    negative = true;
    ++i_;
  }
  if (i_ >= t_.size() || t_[i_].kind != Token::Kind::kWord) return fail("number expected");
  RS4SIM_GSD_TRY(auto number, to_number(t_[i_].text, file_, line_));
  if (!number) return fail("number expected");
  ++i_;
  return negative ? -*number : *number;
}

Result<Value> StatementParser::item() {
  if (i_ >= t_.size()) return fail("value expected");
  const Token& tok = t_[i_];
  if (tok.kind == Token::Kind::kString) {
    ++i_;
    return Value{Value::Kind::kString, 0, 0, tok.text};
  }
  if (tok.kind == Token::Kind::kWord) {
    RS4SIM_GSD_TRY(auto number, to_number(tok.text, file_, line_));
    if (!number) {
      ++i_;
      return Value{Value::Kind::kName, 0, 0, tok.text};
    }
  } else if (!at("-")) {
    return fail("value expected");
  }
  const std::size_t first = i_;
  RS4SIM_GSD_TRY(const std::int64_t low, signed_number());
  // A range is `low-high` with the dash written directly after the low end.
  if (at("-") && !t_[i_].space_before) {
    ++i_;
    RS4SIM_GSD_TRY(const std::int64_t high, signed_number());
    return Value{Value::Kind::kRange, low, high, t_[first].text};
  }
  return Value{Value::Kind::kNumber, low, 0, t_[first].text};
}

Result<std::vector<Value>> StatementParser::comma_list() {
  std::vector<Value> values;
  RS4SIM_GSD_TRY(auto first, item());
  values.push_back(std::move(first));
  while (at(",")) {
    ++i_;
    RS4SIM_GSD_TRY(auto next, item());
    values.push_back(std::move(next));
  }
  return values;
}

Result<Statement> StatementParser::run() {
  Statement st;
  st.line = line_.line;
  st.text = line_.text;
  if (at("#")) {
    ++i_;
    if (i_ >= t_.size() || t_[i_].kind != Token::Kind::kWord || t_[i_].space_before) {
      return fail("keyword expected after '#'");
    }
    st.keyword = "#" + t_[i_++].text;
    if (i_ != t_.size()) return fail("nothing expected after " + st.keyword);
    return st;
  }
  if (i_ < t_.size() && t_[i_].kind == Token::Kind::kWord) {
    RS4SIM_GSD_TRY(auto number, to_number(t_[i_].text, file_, line_));
    if (!number) st.keyword = t_[i_++].text;
  }
  if (st.keyword.empty() && !(i_ < t_.size() && (t_[i_].kind == Token::Kind::kWord || at("-")))) {
    return fail("keyword expected");
  }
  if (!st.keyword.empty() && at("(")) {
    ++i_;
    st.has_args = true;
    RS4SIM_GSD_TRY(st.args, comma_list());
    if (!at(")")) return fail("')' expected");
    ++i_;
  }
  if (!st.keyword.empty() && at("=")) {
    ++i_;
    st.has_equals = true;
    if (i_ == t_.size()) return fail("value expected after '='");
  }
  while (i_ < t_.size()) {
    RS4SIM_GSD_TRY(auto field, comma_list());
    st.fields.push_back(std::move(field));
  }
  return st;
}

}  // namespace

Result<std::vector<LogicalLine>> split_logical_lines(std::string_view text,
                                                     const std::string& file_name) {
  std::vector<LogicalLine> out;
  std::optional<LogicalLine> pending;  // a line that ended in `\`
  int number = 0;
  while (!text.empty() || pending) {
    const std::size_t nl = text.find('\n');
    std::string_view physical = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    const bool last = nl == std::string_view::npos;
    ++number;
    std::string_view body = strip_comment(physical);
    const bool continues = !body.empty() && body.back() == '\\';
    if (continues) body.remove_suffix(1);
    if (!pending)
      pending = LogicalLine{number, {}};
    else
      pending->text += ' ';
    pending->text.append(body);
    if (pending->text.size() > kMaxLogicalLine) {
      return error_at(file_name, pending->line, pending->text.substr(0, 80), "line too long");
    }
    if (!continues || last) {
      if (continues) {
        return error_at(file_name, pending->line, pending->text,
                        "'\\' continues past the end of the file");
      }
      const auto first = pending->text.find_first_not_of(" \t\r\f\v");
      if (first != std::string::npos) out.push_back(std::move(*pending));
      pending.reset();
    }
    if (last) break;
  }
  return out;
}

std::string to_utf8(std::string_view text, bool* converted) {
  // Valid UTF-8 (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF)?
  bool valid = true;
  for (std::size_t i = 0; i < text.size() && valid;) {
    const auto b = static_cast<unsigned char>(text[i]);
    std::size_t n = 0;
    std::uint32_t cp = 0;
    if (b < 0x80) {
      ++i;
      continue;
    }
    if (b >= 0xC2 && b <= 0xDF) {
      n = 1;
      cp = b & 0x1FU;
    } else if (b >= 0xE0 && b <= 0xEF) {
      n = 2;
      cp = b & 0x0FU;
    } else if (b >= 0xF0 && b <= 0xF4) {
      n = 3;
      cp = b & 0x07U;
    } else {
      valid = false;
      break;
    }
    if (i + n >= text.size()) {  // truncated sequence
      valid = false;
      break;
    }
    for (std::size_t k = 1; k <= n; ++k) {
      const auto c = static_cast<unsigned char>(text[i + k]);
      if ((c & 0xC0U) != 0x80U) valid = false;
      cp = (cp << 6) | (c & 0x3FU);
    }
    if (valid && ((n == 2 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) ||
                  (n == 3 && (cp < 0x10000 || cp > 0x10FFFF)))) {
      valid = false;
    }
    i += n + 1;
  }
  if (converted) *converted = !valid;
  if (valid) return std::string(text);
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (const char ch : text) {
    const auto b = static_cast<unsigned char>(ch);
    if (b < 0x80) {
      out += ch;
    } else {  // ISO 8859-1 is the first 256 code points of Unicode
      out += static_cast<char>(0xC0U | (b >> 6));
      out += static_cast<char>(0x80U | (b & 0x3FU));
    }
  }
  return out;
}

Result<Statement> parse_statement(const LogicalLine& line, const std::string& file_name) {
  RS4SIM_GSD_TRY(auto tokens, tokenize(line, file_name));
  return StatementParser(line, file_name, std::move(tokens)).run();
}

}  // namespace rs4sim::gsd::syntax
