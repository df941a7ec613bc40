#include "app/cli/param_sources.h"

#include "app/cli/archive_support.h"
#include "app/runtime/whole_file.h"
#include "rs4/param_doc/parameter_document.h"
#include "rs4/param_doc/set_file.h"
#include "rs4/rs232/rs232_codes.h"
#include "rs4/scanner/parameter_codec.h"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <iterator>
#include <vector>

namespace rs4sim::app::param {
namespace {

using rs4::scanner::ParameterSet;
using rs4::scanner::Password;

std::string read_file(const std::string& path) {
  auto file = read_whole_file(path);
  if (!file) throw ParamCommandError("cannot read " + path + ": " + file.error);
  return std::move(file.bytes);
}

bool all_zero(const ParameterSet& set) {
  return std::all_of(set.passwords.begin(), set.passwords.end(), [](const Password& pw) {
    return std::all_of(pw.begin(), pw.end(), [](std::uint8_t b) { return b == 0; });
  });
}

bool is_empty(const Password& pw) {
  return std::all_of(pw.begin(), pw.end(), [](std::uint8_t b) { return b == 0xFF; });
}

bool ends_with(std::string_view text, std::string_view tail) {
  return text.size() >= tail.size() && text.substr(text.size() - tail.size()) == tail;
}

}  // namespace

SetFile read_set_file(const std::string& path) {
  const std::string text = read_file(path);
  const std::vector<std::uint8_t> raw(text.begin(), text.end());
  const auto contents = rs4::param_doc::read_set_file(raw);
  if (!contents.bytes) {
    throw ParamCommandError(path + ": not an RS4 parameter set file: " + contents.error);
  }
  if (!contents.bytes->warning.empty()) {
    std::cerr << "rs4sim: warning: " << path << ": " << contents.bytes->warning << std::endl;
  }
  const std::vector<std::uint8_t>& bytes = contents.bytes->encoding;
  auto decoded = rs4::scanner::decode(bytes);
  if (decoded.has_error()) {
    throw ParamCommandError(path + ": not an RS4 parameter set: " + decoded.error().message());
  }
  SetFile file{decoded.value(), all_zero(decoded.value())};
  auto checked = file.transfer_form ? rs4::scanner::decode_transfer_form(bytes)
                                    : rs4::scanner::decode_and_validate(bytes);
  if (checked.has_error()) {
    throw ParamCommandError(path + ": invalid RS4 parameter set: " + checked.error().message());
  }
  return file;
}

void write_set_file(const std::string& path, const SetFile& file) {
  const auto bytes = file.transfer_form ? rs4::scanner::encode_for_transfer(file.set)
                                        : rs4::scanner::encode(file.set);
  const auto file_bytes = rs4::param_doc::set_file(bytes);
  archive::write_file_atomically(path, std::string(file_bytes.begin(), file_bytes.end()));
}

ParameterSet read_document_file(const std::string& path, const ParameterSet& base,
                                const rs4::param_doc::CoverageOptions& coverage) {
  const auto result = rs4::param_doc::from_document(read_file(path), base, coverage);
  if (!result) throw ParamCommandError(path + ": " + result.issue.message());
  return *result.set;
}

ParameterSet read_archive_current(const ArchiveStation& station) {
  archive::CommonOptions o;
  o.archive = station.archive;
  o.bus = station.bus;
  o.address = station.address;
  const auto key = archive::station_of(o, "param");
  auto a = archive::open_archive(o, archive::OpenMode::kReadOnly);
  return archive::require_set(archive::unwrap(a->current(key)));
}

Operand read_operand(const std::string& operand, const std::string& archive_file) {
  constexpr std::string_view kArchive = "archive:";
  if (operand.rfind(kArchive, 0) == 0) {
    ArchiveStation station;
    station.archive = archive_file;
    std::string rest = operand.substr(kArchive.size());
    if (const auto slash = rest.find('/'); slash != std::string::npos) {
      station.bus = rest.substr(0, slash);
      rest = rest.substr(slash + 1);
    }
    if (rest.empty() ||
        !std::all_of(rest.begin(), rest.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; }) ||
        rest.size() > 3) {
      throw UsageError("param diff: " + operand + ": expected archive:[BUS/]ADDRESS");
    }
    station.address = std::stoi(rest);
    return {read_archive_current(station), true, false};
  }
  if (ends_with(operand, ".json")) {
    // A diff only shows: a partial protective field is one of the differences it shows.
    return {read_document_file(operand, rs4::scanner::factory_default(), {true}), false, false};
  }
  const SetFile file = read_set_file(operand);
  return {file.set, !file.transfer_form, !file.transfer_form};
}

void align_unknown(Operand& a, Operand& b) {
  if (!a.identity_known) a.set.identity = b.set.identity;
  if (!b.identity_known) b.set.identity = a.set.identity;
  if (!a.passwords_known || !b.passwords_known) b.set.passwords = a.set.passwords;
}

Password password_from_text(std::string_view text) {
  if (text.size() > rs4::scanner::kPasswordLength) {
    throw UsageError("--password has at most 8 characters");
  }
  Password pw;
  pw.fill(0xFF);
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<std::uint8_t>(text[i]);
    if (c < 0x20 || c > 0x7E) throw UsageError("--password: printable ASCII characters only");
    pw[i] = c;
  }
  return pw;
}

bool password_accepted(const SetFile& file, const Password& password) {
  if (file.transfer_form) return true;
  const auto& pws = file.set.passwords;
  if (std::all_of(pws.begin(), pws.end(), is_empty)) {
    return password == rs4::rs232::kFactoryPassword;  // the RS232 port's rule [docs/rs232.md]
  }
  return std::any_of(pws.begin(), pws.end(),
                     [&](const Password& pw) { return !is_empty(pw) && pw == password; });
}

}  // namespace rs4sim::app::param
