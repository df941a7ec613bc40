#pragma once
// Where `rs4sim param` (docs/param.md) reads and writes an RS4 parameter set: a set file
// (the encoding of docs/rs4-scanner.md, full or transfer form), a parameter document
// (.json, rs4/param_doc), a station's current version in the archive, or — later — the
// RS232 port of a running `rs4sim run`. And the --password of `param set`.

#include "app/cli/command.h"
#include "rs4/param_doc/field_coverage.h"
#include "rs4/scanner/parameter_set.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rs4sim::app::param {

// A failure that is not the user's typing (file missing, set invalid): exit 1.
struct ParamCommandError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SetFile {
  rs4::scanner::ParameterSet set;
  // The file held the transfer form (identity and passwords zero, as `archive export` and
  // the proxy carry it); written back in the same form.
  bool transfer_form = false;
};
SetFile read_set_file(const std::string& path);
void write_set_file(const std::string& path, const SetFile& file);

// A document file applied to `base` (factory default for a diff); ParamCommandError with
// "FILE: $.path: reason" when it is refused (a protective field left partly unset too, unless
// `coverage` allows it: --allow-partial-field).
rs4::scanner::ParameterSet read_document_file(const std::string& path,
                                              const rs4::scanner::ParameterSet& base,
                                              const rs4::param_doc::CoverageOptions& coverage);

struct ArchiveStation {
  std::string archive;  // --archive FILE; empty: the default archive
  std::string bus = "default";
  int address = 0;
};
rs4::scanner::ParameterSet read_archive_current(const ArchiveStation& station);

// A diff operand: "archive:[BUS/]ADDR" (with --archive), "*.json" (a document over the
// factory default) or a set file. A document carries neither identity nor passwords, the
// archive and a transfer-form file no passwords: what an operand does not know is not
// compared (align_unknown).
struct Operand {
  rs4::scanner::ParameterSet set;
  bool identity_known = true;
  bool passwords_known = true;
};
Operand read_operand(const std::string& operand, const std::string& archive);
// What one side does not know is taken from the other, so that the diff shows only facts.
void align_unknown(Operand& a, Operand& b);

// --password: up to 8 printable ASCII characters, padded with 0xFF (the set layout of
// docs/rs4-scanner.md; the manual leaves the password format to RS4soft, [RS4 manual §3]);
// UsageError otherwise.
rs4::scanner::Password password_from_text(std::string_view text);
// A set file accepts the write as the RS4's RS232 port does ([docs/rs232.md] "Password"): a
// non-empty user password of the set, or while both are empty the service password "ROD4LE".
// The transfer form carries no passwords and accepts any.
bool password_accepted(const SetFile& file, const rs4::scanner::Password& password);

}  // namespace rs4sim::app::param
