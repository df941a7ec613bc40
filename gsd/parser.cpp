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

constexpr std::array<BlockKind, 7> kBlocks{{
    {"PrmText", "EndPrmText"},
    {"ExtUserPrmData", "EndExtUserPrmData"},
    {"F_ExtUserPrmData", "F_EndExtUserPrmData"},
    {"Module", "EndModule"},
    {"SlotDefinition", "EndSlotDefinition"},
    {"Unit_Diag_Area", "Unit_Diag_Area_End"},
    {"UnitDiagType", "EndUnitDiagType"},
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

}  // namespace

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

bool Statement::is(std::string_view name) const { return iequals(keyword, name); }

Result<File> parse_syntax(std::string_view text, std::string file_name) {
  RS4SIM_GSD_TRY(auto lines, split_logical_lines(text, file_name));
  File file{file_name, {}};
  if (lines.empty()) {
    return Error{GsdError::kMissingHeader, file_name, 1, "",
                 "no keyword line: the file must start with #Profibus_DP"};
  }
  RS4SIM_GSD_TRY(auto header, parse_statement(lines.front(), file_name));
  if (!header.is("#Profibus_DP")) {
    return Error{GsdError::kMissingHeader, file_name, header.line, header.text,
                 "the first keyword line must be #Profibus_DP"};
  }
  const BlockKind* open = nullptr;  // the block being read, if any
  for (std::size_t i = 1; i < lines.size(); ++i) {
    RS4SIM_GSD_TRY(auto st, parse_statement(lines[i], file_name));
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
