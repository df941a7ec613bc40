// libFuzzer: arbitrary bytes as a binary and as a JSON archive import into an in-memory
// SqliteArchive. Must never crash; a rejected import must leave the archive unchanged
// (its full export before == after); an accepted one must leave a sound archive.
#include "storage/archive_file.h"
#include "storage/crc32.h"
#include "storage/sqlite_archive.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>
#include <vector>

namespace {

using namespace rs4sim::storage;

std::unique_ptr<SqliteArchive> fresh_archive() {
  auto archive = SqliteArchive::open(":memory:").value();
  const std::vector<std::uint8_t> blob{'a', 'b', 'c'};  // the corpus's set "abc"
  StoreRequest r;
  r.station = {"line1", 5};
  r.blob = blob;
  r.crc32 = crc32(blob);
  archive->store(r).value();
  return archive;
}

// The archive is always fresh_archive() when an import starts (an accepted import is
// followed by a reset), so its export before every import is this one value.
const std::vector<std::uint8_t>& fresh_export() {
  static const auto bytes = export_binary(*fresh_archive(), {}).value();
  return bytes;
}

template <class Import>
void check(std::unique_ptr<SqliteArchive>& archive, Import import) {
  const auto result = import(*archive);
  if (result.has_error()) {
    if (export_binary(*archive, {}).value() != fresh_export()) std::abort();  // changed
    return;
  }
  if (!archive->check_integrity().value().ok()) std::abort();
  archive = fresh_archive();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static auto archive = fresh_archive();
  const std::span<const std::uint8_t> bytes(data, size);
  check(archive, [&](ParameterArchive& a) { return import_binary(a, bytes); });
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check(archive, [&](ParameterArchive& a) { return import_json(a, text); });
  return 0;
}
