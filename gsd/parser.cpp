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

namespace {

// A block that may hold another: the X_Unit_Diag_Area / Unit_Diag_Area blocks of a
// UnitDiagType block ([PROFIBUS GSD spec UnitDiagType]; a SINAMICS file writes
// `UnitDiagType = 129`, `X_Unit_Diag_Area=24-31` … `X_Unit_Diag_Area_End`, `EndUnitDiagType`).
// The inner block's lines, its head and End line included, stay in the outer block's body.
bool may_nest(const BlockKind& outer, const BlockKind& inner) {
  return outer.open == "UnitDiagType" &&
         (inner.open == "X_Unit_Diag_Area" || inner.open == "Unit_Diag_Area");
}

// Groups statements into entries and blocks.
class BlockReader {
 public:
  explicit BlockReader(File& file) : file_(file) {}
  Result<void> add(Statement st);
  Result<void> finish() const;

 private:
  Error fail(const Statement& st, std::string message) const {
    return structure_error(file_.name, st, std::move(message));
  }
  Result<void> close(Statement st, const BlockKind& ends);

  File& file_;
  const BlockKind* open_ = nullptr;   // the block being read, if any
  const BlockKind* inner_ = nullptr;  // a block nested in it (may_nest)
  int inner_line_ = 0;
};

Result<void> BlockReader::add(Statement st) {
  if (st.is("#Profibus_DP")) return fail(st, "second #Profibus_DP header");
  if (const BlockKind* starts = opener(st)) {
    if (open_ && !inner_ && may_nest(*open_, *starts)) {
      inner_ = starts;
      inner_line_ = st.line;
      file_.entries.back().body->push_back(std::move(st));
      return boost::outcome_v2::success();
    }
    if (open_) {
      return fail(st, std::string(starts->open) + " inside " + std::string(open_->open) +
                          " started at line " +
                          std::to_string(file_.entries.back().statement.line));
    }
    open_ = starts;
    file_.entries.push_back({std::move(st), std::vector<Statement>{}});
  } else if (const BlockKind* ends = closer(st)) {
    return close(std::move(st), *ends);
  } else if (open_) {
    file_.entries.back().body->push_back(std::move(st));
  } else {
    file_.entries.push_back({std::move(st), std::nullopt});
  }
  return boost::outcome_v2::success();
}

Result<void> BlockReader::close(Statement st, const BlockKind& ends) {
  const BlockKind* expected = inner_ ? inner_ : open_;
  if (inner_ && open_ == &ends) {
    return fail(st, std::string(inner_->open) + " started at line " + std::to_string(inner_line_) +
                        " is not closed (" + std::string(inner_->close) + " missing)");
  }
  if (expected != &ends) {
    return fail(st, std::string(ends.close) + " without " + std::string(ends.open));
  }
  if (st.has_args || st.has_equals || !st.fields.empty()) {
    return fail(st, std::string(ends.close) + " takes no value");
  }
  if (inner_) {
    inner_ = nullptr;
    file_.entries.back().body->push_back(std::move(st));
  } else {
    open_ = nullptr;
  }
  return boost::outcome_v2::success();
}

Result<void> BlockReader::finish() const {
  if (!open_) return boost::outcome_v2::success();
  const Statement& head = file_.entries.back().statement;
  return fail(head, std::string(open_->open) + " is not closed (" + std::string(open_->close) +
                        " missing)");
}

Result<Statement> read_header(const std::vector<LogicalLine>& lines, const std::string& name) {
  if (lines.empty()) {
    return Error{GsdError::kMissingHeader, name, 1, "",
                 "no keyword line: the file must start with #Profibus_DP"};
  }
  auto parsed = parse_statement(lines.front(), name);
  if (!parsed) {
    return Error{GsdError::kMissingHeader, name, lines.front().line, lines.front().text,
                 "not a GSD: the first keyword line must be #Profibus_DP"};
  }
  if (!parsed.value().is("#Profibus_DP")) {
    return Error{GsdError::kMissingHeader, name, parsed.value().line, parsed.value().text,
                 "the first keyword line must be #Profibus_DP"};
  }
  return std::move(parsed).value();
}

}  // namespace

Result<File> parse_syntax(std::string_view raw, std::string file_name) {
  bool latin1 = false;
  const std::string text = to_utf8(raw, &latin1);
  RS4SIM_GSD_TRY(auto lines, split_logical_lines(text, file_name));
  File file{file_name, {}, {}, latin1};
  RS4SIM_GSD_TRYV(read_header(lines, file_name));
  file.entries.reserve(lines.size());
  BlockReader blocks(file);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    RS4SIM_GSD_TRY(auto read, read_line(lines[i], file_name, file.warnings));
    if (read) RS4SIM_GSD_TRYV(blocks.add(std::move(*read)));
  }
  RS4SIM_GSD_TRYV(blocks.finish());
  return file;
}

}  // namespace rs4sim::gsd::syntax
