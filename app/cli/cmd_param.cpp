// `rs4sim param get|set|diff`: the parametrisation tool's role (docs/param.md). The RS4
// parameter set as a human-editable JSON document (rs4/param_doc): `get` prints it, `set`
// validates a document against the target's set and writes it with the password, `diff`
// compares two sets field by field. Targets: a set file (--file), a station's current
// version in the archive (get, diff). An invalid document changes nothing.
#include "app/cli/archive_support.h"
#include "app/cli/command.h"
#include "app/cli/param_port.h"
#include "app/cli/param_sources.h"
#include "rs4/param_doc/parameter_document.h"
#include "rs4/report/field_svg.h"
#include "rs4/report/json_writer.h"
#include "rs4/report/parameter_diff.h"

#include <iostream>
#include <memory>
#include <optional>

namespace rs4sim::app {
namespace {

using rs4::scanner::ParameterSet;

struct ParamOptions {
  std::string file;     // --file SET
  std::string archive;  // --archive FILE
  std::string bus = "default";
  std::optional<int> address;
  std::string output;    // get -o FILE
  std::string document;  // set DOCUMENT
  std::string password;  // set --password
  bool dry_run = false;
  bool allow_partial_field = false;  // set --allow-partial-field
  bool json = false;
  std::vector<std::string> operands;  // diff A B
  std::string svg;
  std::string port;  // --port DEV: the RS232 port of a running `rs4sim run --rs232 pty`
};

ParameterSet read_live(const std::string& port) {
  param::SerialPort serial(port);
  const auto live = rs4::param_doc::read_live_set(serial.exchanger());
  if (!live.set) throw param::ParamCommandError(port + ": " + live.error);
  return *live.set;
}

void port_option(CLI::App& sub, ParamOptions& o) {
  sub.add_option("--port", o.port,
                 "the RS4's RS232 port (/dev/pts/N of `rs4sim run --rs232 pty`, PC adapter "
                 "attached)");
}

void source_options(CLI::App& sub, ParamOptions& o) {
  sub.add_option("--file", o.file, "an RS4 parameter set file (docs/rs4-scanner.md encoding)");
  sub.add_option("--archive", o.archive, "archive file (default: the user's archive)");
  sub.add_option("--bus", o.bus, "bus name of the archived station")->capture_default_str();
  sub.add_option("--address", o.address, "PROFIBUS address of the archived station (0..126)");
  port_option(sub, o);
}

ParameterSet read_source(const ParamOptions& o) {
  const int sources = int{!o.file.empty()} + int{o.address.has_value()} + int{!o.port.empty()};
  if (sources != 1) {
    throw UsageError(
        "param get: give exactly one source: --file SET, --port DEV or --address N [--archive F]");
  }
  if (!o.file.empty()) return param::read_set_file(o.file).set;
  if (!o.port.empty()) return read_live(o.port);
  return param::read_archive_current({o.archive, o.bus, *o.address});
}

int run_get(const ParamOptions& o) {
  const std::string document = rs4::param_doc::to_document(read_source(o));
  if (o.output.empty()) {
    std::cout << document;
  } else {
    archive::write_file_atomically(o.output, document);
  }
  return 0;
}

void print_set_result(const ParamOptions& o, const rs4::report::ParameterDiff& d, bool written) {
  if (o.json) {
    rs4::report::JsonWriter w;
    w.begin_object().field("target", o.port.empty() ? o.file : o.port);
    w.field("document", o.document);
    w.field("written", written).key("diff").raw(rs4::report::render_json(d));
    std::cout << w.end_object().str() << "\n";
    return;
  }
  std::cout << (o.port.empty() ? o.file : o.port) << ": "
            << (written     ? "written"
                : d.empty() ? "unchanged"
                            : "not written (--dry-run)")
            << "\n"
            << rs4::report::render_text(d);
}

// Refusals print "nothing changed" and exit 1.
int refused(const std::string& what) {
  std::cerr << "rs4sim: param set: " << what << "\nrs4sim: param set: nothing changed\n";
  return 1;
}

int run_set_live(const ParamOptions& o, const rs4::scanner::Password& password) {
  param::SerialPort serial(o.port);
  const auto live = rs4::param_doc::read_live_set(serial.exchanger());
  if (!live.set) throw param::ParamCommandError(o.port + ": " + live.error);
  ParameterSet updated;
  try {
    updated = param::read_document_file(o.document, *live.set, {o.allow_partial_field});
  } catch (const param::ParamCommandError& e) {
    return refused(e.what());
  }
  const auto d = rs4::report::diff(*live.set, updated);
  const bool write = !o.dry_run && !d.empty();
  if (write) {
    // The RS4 checks the password and validates again before it applies anything.
    const auto error = rs4::param_doc::write_live_set(serial.exchanger(), updated, password);
    if (!error.empty()) return refused(o.port + ": " + error);
  }
  print_set_result(o, d, write);
  return 0;
}

int run_set(const ParamOptions& o) {
  if (o.document.empty()) throw UsageError("param set: give the DOCUMENT to write");
  if (o.file.empty() == o.port.empty()) {
    throw UsageError("param set: give one target: --file SET or --port DEV");
  }
  const auto password = param::password_from_text(o.password);
  if (!o.port.empty()) return run_set_live(o, password);
  param::SetFile target = param::read_set_file(o.file);
  ParameterSet updated;
  try {
    updated = param::read_document_file(o.document, target.set, {o.allow_partial_field});
  } catch (const param::ParamCommandError& e) {
    return refused(e.what());
  }
  if (!param::password_accepted(target, password)) {
    return refused(o.file + ": wrong password (--password)");
  }
  const auto d = rs4::report::diff(target.set, updated);
  const bool write = !o.dry_run && !d.empty();
  if (write) {
    target.set = updated;
    param::write_set_file(o.file, target);
  }
  print_set_result(o, d, write);
  return 0;
}

int run_diff(const ParamOptions& o) {
  if (o.operands.size() != 2) throw UsageError("param diff: give two sets A B");
  auto read = [&o](const std::string& operand) -> param::Operand {
    if (operand != "live") return param::read_operand(operand, o.archive);
    if (o.port.empty()) throw UsageError("param diff: the operand live needs --port DEV");
    return {read_live(o.port), true, false};  // passwords never leave the device
  };
  param::Operand first = read(o.operands[0]);
  param::Operand second = read(o.operands[1]);
  param::align_unknown(first, second);
  const ParameterSet& a = first.set;
  const ParameterSet& b = second.set;
  const auto d = rs4::report::diff(a, b);
  if (!o.svg.empty()) {
    const std::string title = o.operands[0] + " -> " + o.operands[1];
    archive::write_file_atomically(
        o.svg, rs4::report::field_diff_svg(a, b, {title, o.operands[0], o.operands[1]}));
  }
  std::cout << (o.json ? rs4::report::render_json(d) + "\n" : rs4::report::render_text(d));
  return 0;
}

void get_options(CLI::App& sub, ParamOptions& o) {
  source_options(sub, o);
  sub.add_option("-o,--output", o.output, "write the document to FILE instead of stdout");
}

void set_options(CLI::App& sub, ParamOptions& o) {
  sub.add_option("DOCUMENT", o.document, "the parameter document (JSON, docs/param.md)");
  sub.add_option("--file", o.file, "the RS4 parameter set file to change");
  port_option(sub, o);
  sub.add_option("--password", o.password,
                 "the password for writing (never part of a document; empty: none)");
  sub.add_flag("--dry-run", o.dry_run, "validate and show the changes, write nothing");
  sub.add_flag("--allow-partial-field", o.allow_partial_field,
               "accept a protective field with segments left unset (0 mm: no protective field "
               "on those beams); without it such a document is refused");
  sub.add_flag("--json", o.json, "print one JSON document");
}

void diff_options(CLI::App& sub, ParamOptions& o) {
  sub.add_option("A B", o.operands,
                 "two sets: FILE.json (document over the factory default), a set file, "
                 "archive:[BUS/]ADDRESS (with --archive) or live (with --port)");
  sub.add_option("--archive", o.archive, "archive file for archive: operands");
  port_option(sub, o);
  sub.add_flag("--json", o.json, "print the difference as one JSON document");
  sub.add_option("--svg", o.svg, "also write an SVG picture of both sets' field pairs to FILE");
}

constexpr SubCommand<ParamOptions> kSubCommands[] = {
    {"get", "Print the parameter set as a JSON document", get_options, run_get},
    {"set", "Validate a JSON document and write it with the password", set_options, run_set},
    {"diff", "Field-level difference of two parameter sets", diff_options, run_diff},
};

const CommandRegistration kRegistration{
    "param", "The RS4 parameter set as a JSON document: get, set, diff (docs/param.md)",
    [](CLI::App& cmd) -> Action { return sub_commands(cmd, kSubCommands); }};

}  // namespace
}  // namespace rs4sim::app
