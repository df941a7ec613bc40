#pragma once
// GSD syntax ([PROFIBUS GSD spec syntax]): what the text says, before any meaning is given to
// it. The parser turns a GSD text into logical lines (comments `;` removed, lines ending
// in `\` joined), each line into a Statement (keyword, optional `(args)`, optional `=`,
// value fields) and groups the statements between block keywords (Module…EndModule,
// PrmText…EndPrmText, ExtUserPrmData…EndExtUserPrmData, SlotDefinition…,
// Unit_Diag_Area…Unit_Diag_Area_End, UnitDiagType…EndUnitDiagType). Keywords compare
// case-insensitively; the interpreter (interp.h) gives them meaning.

#include "gsd/error.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs4sim::gsd::syntax {

struct Value {
  enum class Kind { kNumber, kString, kName, kRange };
  Kind kind = Kind::kNumber;
  std::int64_t number = 0;  // kNumber; kRange: low end
  std::int64_t high = 0;    // kRange: high end
  std::string text;         // kString (without quotes), kName; the source text otherwise

  bool is_number() const { return kind == Kind::kNumber; }
  bool is_string() const { return kind == Kind::kString; }
  bool is_range() const { return kind == Kind::kRange; }
};

// Values separated by commas form one field; whitespace starts the next field:
//   `Module = "DI 8" 0x10,0x20`  → fields ["DI 8"], [0x10, 0x20]
//   `BitArea(2-3) 1 0-3`         → args [2-3], fields [1], [0-3]
using Field = std::vector<Value>;

struct Statement {
  int line = 0;           // first physical line of the logical line (1-based)
  std::string keyword;    // as written; "#Profibus_DP" for the header; empty for a
                          // line of bare values (a module's reference number)
  bool has_args = false;  // `keyword(args)`
  std::vector<Value> args;
  bool has_equals = false;
  std::vector<Field> fields;
  std::string text;  // the logical line, comments removed, for error messages

  bool is(std::string_view name) const;  // case-insensitive keyword comparison
};

struct Entry {
  Statement statement;                         // a plain statement or a block's head
  std::optional<std::vector<Statement>> body;  // set for blocks (without the End line)
};

struct File {
  std::string name;
  std::vector<Entry> entries;     // in file order, starting after #Profibus_DP
  std::vector<Warning> warnings;  // lines skipped: words that are not GSD keywords
  bool latin1 = false;            // the text was not UTF-8: read as ISO 8859-1
};

// A keyword of the GSD specification (revisions 1–5, slave and master keywords;
// case-insensitive). A line whose keyword is not one is skipped with a warning, whatever
// follows it; a line of a known keyword must be well formed.
bool is_gsd_keyword(std::string_view keyword);

// GSD files are ISO 8859-1 ([PROFIBUS GSD spec] character set; the French and German
// variants carry letters such as é, ä in their strings and comments). Text that is valid
// UTF-8 is returned as it is; anything else is read as ISO 8859-1 and converted to UTF-8.
// `converted` (if given) tells which.
std::string to_utf8(std::string_view text, bool* converted = nullptr);

bool iequals(std::string_view a, std::string_view b);

// The whole syntax stage. Errors carry file:line and the offending text.
Result<File> parse_syntax(std::string_view text, std::string file_name);

// The lexer stage on its own (exposed for tests and the fuzzer).
struct LogicalLine {
  int line = 0;
  std::string text;
};
Result<std::vector<LogicalLine>> split_logical_lines(std::string_view text,
                                                     const std::string& file_name);
Result<Statement> parse_statement(const LogicalLine& line, const std::string& file_name);

}  // namespace rs4sim::gsd::syntax
