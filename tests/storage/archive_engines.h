#pragma once
// The engines the archive's contract suite runs on, each with a way to look at and damage the
// stored rows behind the archive's back (the engine's own client library, not the code under
// test):
//   - "sqlite": a file in a temporary directory;
//   - "postgresql": a schema of its own (dropped afterwards) on the server the ctest fixture
//     started (tests/storage/postgres_server.sh writes its URI to the file named by
//     RS4SIM_TEST_POSTGRES_URI_FILE; RS4SIM_TEST_POSTGRES_URI names a server directly).
// Without a server the PostgreSQL half skips itself, unless RS4SIM_REQUIRE_POSTGRES=1, when it
// fails: in CI it must run.

#include "storage/open_archive.h"
#include "tests/storage/archive_test_support.h"

#include <libpq-fe.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::storage::testing {

// The test server's URI; nullopt when none was started.
inline std::optional<std::string> postgres_uri() {
  if (const char* uri = std::getenv("RS4SIM_TEST_POSTGRES_URI"); uri != nullptr && *uri != 0) {
    return std::string(uri);
  }
  const char* file = std::getenv("RS4SIM_TEST_POSTGRES_URI_FILE");
  if (file == nullptr) return std::nullopt;
  std::ifstream in(file);
  std::string uri;
  if (!std::getline(in, uri) || uri.empty()) return std::nullopt;
  return uri;
}

inline bool postgres_required() {
  const char* v = std::getenv("RS4SIM_REQUIRE_POSTGRES");
  return v != nullptr && std::string(v) == "1";
}

// `uri` with libpq's options parameter setting the search_path to `schema`.
inline std::string with_search_path(const std::string& uri, const std::string& schema) {
  return uri + (uri.find('?') == std::string::npos ? "?" : "&") +
         "options=-csearch_path%3D" + schema;
}

// One raw libpq connection: runs SQL, returns every row as text.
class RawPg {
 public:
  explicit RawPg(const std::string& uri) : conn_(PQconnectdb(uri.c_str())) {
    if (PQstatus(conn_) != CONNECTION_OK) {
      ADD_FAILURE() << "raw connection: " << PQerrorMessage(conn_);
    }
  }
  RawPg(const RawPg&) = delete;
  RawPg& operator=(const RawPg&) = delete;
  ~RawPg() { PQfinish(conn_); }
  std::vector<std::vector<std::string>> rows(const std::string& sql) {
    PGresult* r = PQexec(conn_, sql.c_str());
    std::vector<std::vector<std::string>> out;
    const auto status = PQresultStatus(r);
    if (status != PGRES_TUPLES_OK && status != PGRES_COMMAND_OK) {
      ADD_FAILURE() << sql << ": " << PQerrorMessage(conn_);
    }
    for (int i = 0; i < PQntuples(r); ++i) {
      auto& row = out.emplace_back();
      for (int c = 0; c < PQnfields(r); ++c) row.emplace_back(PQgetvalue(r, i, c));
    }
    PQclear(r);
    return out;
  }
  void exec(const std::string& sql) { rows(sql); }
  PGconn* handle() const { return conn_; }

 private:
  PGconn* conn_;
};

class Engine {
 public:
  virtual ~Engine() = default;
  // What --archive would be: the file, or the URI with its search_path.
  virtual std::string location() const = 0;
  std::unique_ptr<ParameterArchive> open(const OpenOptions& options = {}) const {
    auto opened = open_archive(location(), options);
    if (!opened) throw std::runtime_error(opened.error().message);
    return std::move(opened).value();
  }
  // Every table's rows, read on a connection of the engine's own library.
  virtual std::string digest() = 0;
  // Overwrites every stored blob with one zero byte.
  virtual void damage_blobs() = 0;
};

class SqliteEngine final : public Engine {
 public:
  std::string location() const override { return dir_.file("archive.sqlite3").string(); }
  std::string digest() override { return testing::digest(location()); }
  void damage_blobs() override {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(location().c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "UPDATE parameter_sets SET blob = x'00'", nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(db);
  }

 private:
  TempDir dir_;
};

class PgEngine final : public Engine {
 public:
  explicit PgEngine(std::string server) : server_(std::move(server)), raw_(server_) {
    static int counter = 0;
    schema_ = "rs4sim_test_" + std::to_string(::getpid()) + "_" + std::to_string(++counter);
    raw_.exec("DROP SCHEMA IF EXISTS " + schema_ + " CASCADE");
    raw_.exec("CREATE SCHEMA " + schema_);
  }
  // An idle connection holds no lock: the test's archives may still be open.
  ~PgEngine() override { raw_.exec("DROP SCHEMA IF EXISTS " + schema_ + " CASCADE"); }
  std::string location() const override { return with_search_path(server_, schema_); }
  const std::string& server() const { return server_; }
  const std::string& schema() const { return schema_; }
  RawPg& raw() { return raw_; }
  std::string digest() override {
    std::string out;
    for (const auto& table :
         raw_.rows("SELECT tablename FROM pg_tables WHERE schemaname = '" + schema_ +
                   "' ORDER BY tablename")) {
      out += "table " + table[0] + "\n";
      for (const auto& row :
           raw_.rows("SELECT * FROM " + schema_ + "." + table[0] + " ORDER BY 1, 2")) {
        for (const auto& value : row) out += std::to_string(value.size()) + ":" + value + "|";
        out += "\n";
      }
    }
    return out;
  }
  void damage_blobs() override {
    raw_.exec("UPDATE " + schema_ + ".parameter_sets SET blob = '\\x00'::bytea");
  }

 private:
  std::string server_;
  RawPg raw_;
  std::string schema_;
};

// The engine named `name`; nullptr when there is no server (the test then skips itself), with
// a failure added when a server is required.
inline std::unique_ptr<Engine> make_engine(const std::string& name) {
  if (name == "sqlite") return std::make_unique<SqliteEngine>();
  const auto uri = postgres_uri();
  if (!uri) {
    if (postgres_required()) {
      ADD_FAILURE() << "RS4SIM_REQUIRE_POSTGRES=1 but no PostgreSQL server was started "
                       "(tests/storage/postgres_server.sh)";
    }
    return nullptr;
  }
  return std::make_unique<PgEngine>(*uri);
}

// A suite on every engine (TEST_P with ::testing::Values("sqlite", "postgresql")): the engine
// and its archive, open; skipped without a PostgreSQL server.
class EngineTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    engine_ = make_engine(GetParam());
    if (!engine_) GTEST_SKIP() << "no PostgreSQL server (tests/storage/postgres_server.sh)";
    archive_ = engine_->open();
  }
  std::unique_ptr<Engine> engine_;
  std::unique_ptr<ParameterArchive> archive_;
};

inline std::string engine_name(const ::testing::TestParamInfo<std::string>& info) {
  return info.param;
}

}  // namespace rs4sim::storage::testing
