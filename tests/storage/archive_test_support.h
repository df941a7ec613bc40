#pragma once
// Shared by the storage tests, benchmarks and the crash-test writer: temporary
// directories, distinct blobs, store requests, and a digest of a whole archive file read
// through a separate raw SQLite connection (so "unchanged" is checked independently of
// the code under test).

#include "storage/crc32.h"
#include "storage/types.h"

#include <sqlite3.h>

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace rs4sim::storage::testing {

inline constexpr std::size_t kRealisticSetSize = 8507;  // an RS4 parameter set's size

class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "rs4sim-storage-XXXXXX");
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::filesystem::path file(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// Deterministic pseudo-random bytes: distinct seeds give distinct blobs.
inline std::vector<std::uint8_t> make_blob(std::uint64_t seed,
                                           std::size_t size = kRealisticSetSize) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> blob(size);
  for (auto& b : blob) b = static_cast<std::uint8_t>(rng());
  return blob;
}

inline Timestamp at_ms(std::int64_t ms) { return Timestamp{std::chrono::milliseconds{ms}}; }

inline StoreRequest request(const StationKey& station, const std::vector<std::uint8_t>& blob,
                            std::int64_t at = 1'700'000'000'000) {
  StoreRequest r;
  r.station = station;
  r.device_type = "TEST-DEVICE";
  r.serial_number = "SN-1";
  r.blob = blob;
  r.crc32 = crc32(blob);
  r.summary = "{\"test\":true}";
  r.source = VersionSource::kUpload;
  r.at = at_ms(at);
  return r;
}

// Every table's rows plus the schema version, as text, read on its own connection.
inline std::string digest(const std::filesystem::path& file) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(db);
    return "<cannot open>";
  }
  std::string out;
  auto collect = [&](const std::string& sql) {
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) != SQLITE_OK) {
      out += "<error " + sql + ">";
      return std::vector<std::string>{};
    }
    std::vector<std::string> first_column;
    while (sqlite3_step(s) == SQLITE_ROW) {
      for (int c = 0; c < sqlite3_column_count(s); ++c) {
        const auto* p = static_cast<const char*>(sqlite3_column_blob(s, c));
        std::string value(p == nullptr ? "" : p,
                          static_cast<std::size_t>(sqlite3_column_bytes(s, c)));
        if (c == 0) first_column.push_back(value);
        out += std::to_string(value.size()) + ":" + value + "|";
      }
      out += "\n";
    }
    sqlite3_finalize(s);
    return first_column;
  };
  collect("PRAGMA user_version");
  const auto tables = collect("SELECT name FROM sqlite_schema WHERE type = 'table' ORDER BY name");
  for (const auto& t : tables) {
    out += "table " + t + "\n";
    collect("SELECT * FROM \"" + t + "\" ORDER BY rowid");
  }
  sqlite3_close(db);
  return out;
}

}  // namespace rs4sim::storage::testing
