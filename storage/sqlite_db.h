#pragma once
// Thin RAII layer over the SQLite C API (https://sqlite.org/c3ref/intro.html): one owner
// per sqlite3* and sqlite3_stmt*, prepared statements only (cached per SQL text), a
// transaction guard that rolls back unless committed, SQLite result codes mapped to
// ArchiveError. Internal to storage/.

#include "storage/errors.h"

#include <sqlite3.h>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace rs4sim::storage::sqlite {

// Maps a SQLite result code (primary or extended) to our error, with `what` as context.
ArchiveFailure error_from(int rc, sqlite3* db, std::string_view what);

class Statement {
 public:
  Statement(sqlite3_stmt* stmt) noexcept : stmt_(stmt) {}
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  ~Statement();

  // Binds by 1-based position.
  void bind(int index, std::int64_t value);
  void bind(int index, std::string_view text);
  void bind(int index, std::span<const std::uint8_t> blob);
  void bind_null(int index);

  int step() noexcept { return sqlite3_step(stmt_); }  // SQLITE_ROW / SQLITE_DONE / error
  void reset() noexcept;

  std::int64_t int64(int column) const noexcept { return sqlite3_column_int64(stmt_, column); }
  bool is_null(int column) const noexcept;
  std::string text(int column) const;
  std::vector<std::uint8_t> blob(int column) const;

 private:
  sqlite3_stmt* stmt_;
};

// A cached statement in use: reset and unbound when it goes out of scope.
class StatementUse {
 public:
  StatementUse(Statement& s) noexcept : s_(&s) {}
  StatementUse(StatementUse&& other) noexcept : s_(other.s_) { other.s_ = nullptr; }
  StatementUse(const StatementUse&) = delete;
  StatementUse& operator=(const StatementUse&) = delete;
  StatementUse& operator=(StatementUse&&) = delete;
  ~StatementUse() {
    if (s_ != nullptr) s_->reset();
  }
  Statement* operator->() const noexcept { return s_; }
  Statement& operator*() const noexcept { return *s_; }

 private:
  Statement* s_;
};

class Database {
 public:
  // flags: SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, or SQLITE_OPEN_READONLY.
  static Result<std::unique_ptr<Database>> open(const std::string& path, int flags);
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  ~Database();

  sqlite3* handle() const noexcept { return db_; }
  const std::string& path() const noexcept { return path_; }

  // The statement for `sql`, prepared once and kept for the connection's lifetime.
  Result<StatementUse> statement(std::string_view sql);
  // Runs a statement without results (pragmas, DDL, BEGIN/COMMIT).
  Result<void> exec(std::string_view sql);
  // A statement returning one integer (PRAGMA user_version, SELECT count(*)).
  Result<std::int64_t> query_int(std::string_view sql);
  // Steps `s` to SQLITE_DONE; an error is mapped with `what` as context.
  Result<void> run(Statement& s, std::string_view what);
  ArchiveFailure error(int rc, std::string_view what) const { return error_from(rc, db_, what); }

 private:
  Database(sqlite3* db, std::string path) noexcept : db_(db), path_(std::move(path)) {}
  sqlite3* db_;
  std::string path_;
  std::unordered_map<std::string, std::unique_ptr<Statement>> cache_;
};

// BEGIN IMMEDIATE (begin()) or BEGIN (begin_read()); ROLLBACK in the destructor unless
// commit() succeeded.
class Transaction {
 public:
  static Result<Transaction> begin(Database& db);
  // BEGIN (deferred): a consistent view for several reads.
  static Result<Transaction> begin_read(Database& db);
  Transaction(Transaction&& other) noexcept : db_(other.db_) { other.db_ = nullptr; }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  Transaction& operator=(Transaction&&) = delete;
  ~Transaction();
  Result<void> commit();

 private:
  explicit Transaction(Database& db) noexcept : db_(&db) {}
  Database* db_;
};

}  // namespace rs4sim::storage::sqlite
