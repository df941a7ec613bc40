// GSD parser: statements → entries with blocks ([PROFIBUS GSD spec syntax]). Checks only the
// structure: the #Profibus_DP header first, every block closed by its own End keyword,
// no block inside another.
#include "gsd/syntax.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace rs4sim::gsd::syntax {
namespace {

struct BlockKind {
  std::string_view open;
  std::string_view close;
};

constexpr std::array<BlockKind, 8> kBlocks{{
    {"PrmText", "EndPrmText"},
    {"ExtUserPrmData", "EndExtUserPrmData"},
    {"F_ExtUserPrmData", "F_EndExtUserPrmData"},
    {"Module", "EndModule"},
    {"SlotDefinition", "EndSlotDefinition"},
    {"Unit_Diag_Area", "Unit_Diag_Area_End"},
    {"UnitDiagType", "EndUnitDiagType"},
    {"X_Unit_Diag_Area", "X_Unit_Diag_Area_End"},
}};

const BlockKind* opener(const Statement& st) {
  for (const auto& b : kBlocks) {
    if (st.is(b.open)) return &b;
  }
  return nullptr;
}
const BlockKind* closer(const Statement& st) {
  for (const auto& b : kBlocks) {
    if (st.is(b.close)) return &b;
  }
  return nullptr;
}

Error structure_error(const std::string& file, const Statement& st, std::string message) {
  return Error{GsdError::kBlockStructure, file, st.line, st.text, std::move(message)};
}

// The word a logical line starts with, up to a blank, `=` or `(`.
std::string_view head_word(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\f\v");
  if (first == std::string_view::npos) return {};
  text.remove_prefix(first);
  return text.substr(0, text.find_first_of(" \t\r\f\v=("));
}

// A line whose first word is not a GSD keyword is skipped with a warning, whether or not the
// rest parses (`Unit_Diag_!Bit(3) = "x"`: engineering tools skip it). A line of bare values
// (a module's reference number) has no keyword and stays; a known keyword must parse.
Result<std::optional<Statement>> read_line(const LogicalLine& line, const std::string& file,
                                           std::vector<Warning>& warnings) {
  auto st = parse_statement(line, file);
  const std::string_view head = head_word(line.text);
  const bool word_line =
      !head.empty() && (std::isalpha(static_cast<unsigned char>(head[0])) != 0 || head[0] == '_');
  const std::string_view keyword = st ? std::string_view(st.value().keyword) : head;
  const bool unknown = st ? (!keyword.empty() && keyword[0] != '#' && !is_gsd_keyword(keyword))
                          : (word_line && !is_gsd_keyword(head));
  if (!unknown) {
    if (!st) return std::move(st).error();
    return std::optional<Statement>(std::move(st).value());
  }
  std::string message = "'" + std::string(keyword) + "' is not a GSD keyword, line skipped";
  if (!st) message += " (" + st.error().message + ")";
  warnings.push_back({file, line.line, line.text, std::move(message)});
  return std::optional<Statement>{};
}

}  // namespace

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

bool Statement::is(std::string_view name) const { return iequals(keyword, name); }

Result<File> parse_syntax(std::string_view raw, std::string file_name) {
  bool latin1 = false;
  const std::string text = to_utf8(raw, &latin1);
  RS4SIM_GSD_TRY(auto lines, split_logical_lines(text, file_name));
  File file{file_name, {}, {}, latin1};
  if (lines.empty()) {
    return Error{GsdError::kMissingHeader, file_name, 1, "",
                 "no keyword line: the file must start with #Profibus_DP"};
  }
  auto parsed_header = parse_statement(lines.front(), file_name);
  if (!parsed_header) {
    return Error{GsdError::kMissingHeader, file_name, lines.front().line, lines.front().text,
                 "not a GSD: the first keyword line must be #Profibus_DP"};
  }
  Statement header = std::move(parsed_header).value();
  if (!header.is("#Profibus_DP")) {
    return Error{GsdError::kMissingHeader, file_name, header.line, header.text,
                 "the first keyword line must be #Profibus_DP"};
  }
  const BlockKind* open = nullptr;  // the block being read, if any
  for (std::size_t i = 1; i < lines.size(); ++i) {
    RS4SIM_GSD_TRY(auto read, read_line(lines[i], file_name, file.warnings));
    if (!read) continue;
    Statement st = std::move(*read);
    if (st.is("#Profibus_DP")) return structure_error(file_name, st, "second #Profibus_DP header");
    if (const BlockKind* starts = opener(st)) {
      if (open) {
        return structure_error(file_name, st,
                               std::string(starts->open) + " inside " + std::string(open->open) +
                                   " started at line " +
                                   std::to_string(file.entries.back().statement.line));
      }
      open = starts;
      file.entries.push_back({std::move(st), std::vector<Statement>{}});
    } else if (const BlockKind* ends = closer(st)) {
      if (open != ends) {
        return structure_error(file_name, st,
                               std::string(ends->close) + " without " + std::string(ends->open));
      }
      if (st.has_args || st.has_equals || !st.fields.empty()) {
        return structure_error(file_name, st, std::string(ends->close) + " takes no value");
      }
      open = nullptr;
    } else if (open) {
      file.entries.back().body->push_back(std::move(st));
    } else {
      file.entries.push_back({std::move(st), std::nullopt});
    }
  }
  if (open) {
    const Statement& head = file.entries.back().statement;
    return structure_error(
        file_name, head,
        std::string(open->open) + " is not closed (" + std::string(open->close) + " missing)");
  }
  return file;
}

}  // namespace rs4sim::gsd::syntax
