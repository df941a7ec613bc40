// A walk over valid JSON text that skips every value it does not enter (locate.h). Values are
// skipped by counting brackets outside strings, without recursion.
#include "json/locate.h"

#include <cctype>
#include <string>

namespace rs4sim::json {
namespace {

std::size_t skip_space(std::string_view t, std::size_t i) {
  while (i < t.size() && (t[i] == ' ' || t[i] == '\t' || t[i] == '\n' || t[i] == '\r')) ++i;
  return i;
}

std::size_t skip_string(std::string_view t, std::size_t i) {  // i at the opening quote
  for (++i; i < t.size(); ++i) {
    if (t[i] == '\\') {
      ++i;
    } else if (t[i] == '"') {
      return i + 1;
    }
  }
  return t.size();
}

std::size_t skip_value(std::string_view t, std::size_t i) {
  if (i < t.size() && t[i] == '"') return skip_string(t, i);
  std::size_t depth = 0;
  while (i < t.size()) {
    const char c = t[i];
    if (c == '"') {
      i = skip_string(t, i);
      continue;
    }
    if (c == '[' || c == '{') ++depth;
    if (c == ']' || c == '}' || c == ',') {
      if (depth == 0) return i;
      if (c != ',' && --depth == 0) return i + 1;
    }
    if (depth == 0 && (c == ' ' || c == '\t' || c == '\n' || c == '\r')) return i;
    ++i;
  }
  return i;
}

std::string camel(std::string_view name) {
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (name[i] == '_' && i + 1 < name.size()) {
      out += static_cast<char>(std::toupper(static_cast<unsigned char>(name[++i])));
    } else {
      out += name[i];
    }
  }
  return out;
}

// The offset of the value of member `name` of the object at i, or of element `index` of the
// array at i (name empty); npos when there is none.
std::size_t enter(std::string_view t, std::size_t i, std::string_view name, std::size_t index) {
  const char open = name.empty() ? '[' : '{';
  if (i >= t.size() || t[i] != open) return std::string_view::npos;
  const std::string alias = camel(name);
  for (std::size_t k = 0;; ++k) {
    i = skip_space(t, i + 1);
    if (i >= t.size() || t[i] == ']' || t[i] == '}') return std::string_view::npos;
    bool match = k == index;
    if (!name.empty()) {
      const std::size_t end = skip_string(t, i);
      const auto key = t.substr(i + 1, end - i - 2);
      match = key == name || key == alias;
      i = skip_space(t, end) + 1;  // past ':'
    }
    i = skip_space(t, i);
    if (match) return i;
    i = skip_space(t, skip_value(t, i));
    if (i >= t.size() || t[i] != ',') return std::string_view::npos;
  }
}

}  // namespace

std::optional<std::size_t> offset_of_member(std::string_view text, std::string_view path) {
  std::size_t at = skip_space(text, 0);
  for (std::size_t p = 0; p < path.size() && at != std::string_view::npos;) {
    if (path[p] == '.') ++p;
    if (p < path.size() && path[p] == '[') {
      const auto close = path.find(']', p);
      if (close == std::string_view::npos) return std::nullopt;
      std::size_t index = 0;
      for (std::size_t d = p + 1; d < close; ++d) {
        if (!std::isdigit(static_cast<unsigned char>(path[d]))) return std::nullopt;
        index = index * 10 + static_cast<std::size_t>(path[d] - '0');
      }
      at = enter(text, at, {}, index);
      p = close + 1;
      continue;
    }
    const auto end = path.find_first_of(".[", p);
    const auto name = path.substr(p, end == std::string_view::npos ? path.size() - p : end - p);
    if (name.empty()) return std::nullopt;
    at = enter(text, at, name, 0);
    p = end == std::string_view::npos ? path.size() : end;
  }
  if (at == std::string_view::npos) return std::nullopt;
  return at;
}

}  // namespace rs4sim::json
