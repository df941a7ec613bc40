#pragma once
// A thin owner of one libpq connection (internal to storage/): statements prepared once per
// connection and run with their parameters bound (never spliced into SQL), results in
// libpq's binary format, SQLSTATEs mapped to ArchiveError, and the connection string shown
// without its password. Not thread-safe: one owner, as SqliteArchive.

#include "storage/errors.h"

#include <libpq-fe.h>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace rs4sim::storage::pg {

// SQLSTATEs the archive reacts to [PostgreSQL 15 manual, Appendix A].
inline constexpr std::string_view kSerializationFailure = "40001";
inline constexpr std::string_view kDeadlockDetected = "40P01";
inline constexpr std::string_view kUniqueViolation = "23505";

// "postgresql://user@host:port/db" from a URI or key=value string, password left out; the
// text itself when libpq cannot parse it (then it holds no parsed password either: a
// string libpq cannot parse is shown up to its first "password").
std::string redacted(std::string_view conninfo);
// True for the URIs libpq takes ("postgresql://" or "postgres://").
bool is_postgres_uri(std::string_view location) noexcept;

// Parameters of one statement: integers and text in text form, bytes in binary form.
class Params {
 public:
  Params& add(std::int64_t v);
  Params& add(std::string_view v);
  Params& add(std::span<const std::uint8_t> v);
  Params& add_null();
  Params& add_bool(bool v) { return add(std::string_view(v ? "true" : "false")); }

  int size() const noexcept { return static_cast<int>(storage_.size()); }
  // Pointers into this object: valid until the next add().
  std::vector<const char*> values() const;
  const int* lengths() const noexcept { return lengths_.data(); }
  const int* formats() const noexcept { return formats_.data(); }

 private:
  std::vector<std::string> storage_;  // the bytes of each parameter
  std::vector<bool> null_;
  std::vector<int> lengths_;
  std::vector<int> formats_;
};

// One statement's rows, read in binary format. Columns must be int2/int4/int8, bool, text
// or bytea (casts in the SQL make sure).
class Rows {
 public:
  explicit Rows(PGresult* r) : r_(r, &PQclear) {}
  int count() const noexcept { return PQntuples(r_.get()); }
  bool is_null(int row, int col) const noexcept { return PQgetisnull(r_.get(), row, col) != 0; }
  std::int64_t int64(int row, int col) const;
  bool boolean(int row, int col) const;
  std::string text(int row, int col) const;
  std::vector<std::uint8_t> bytes(int row, int col) const;
  std::int64_t affected() const;  // rows an INSERT/UPDATE/DELETE changed
  PGresult* raw() const noexcept { return r_.get(); }

 private:
  std::unique_ptr<PGresult, decltype(&PQclear)> r_;
};

class Connection {
 public:
  // Connects (libpq's URI or key=value string, PG* environment variables for what it
  // leaves out); kIo naming the server, never the password.
  static Result<std::unique_ptr<Connection>> open(const std::string& conninfo);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // Runs `sql` (prepared on first use on this connection) with `params`.
  Result<Rows> query(std::string_view sql, const Params& params, std::string_view what);
  Result<Rows> query(std::string_view sql, std::string_view what) {
    return query(sql, Params{}, what);
  }
  // A statement without parameters or rows (BEGIN, COMMIT, DDL): the simple protocol, so
  // a script of several statements runs as one.
  Result<void> exec(std::string_view sql, std::string_view what);

  // The server is gone (terminated backend, network): a fresh connection replaces it before
  // the next transaction, with the statements prepared again on use.
  Result<void> reconnect_if_lost();
  bool lost() const noexcept { return PQstatus(conn_) != CONNECTION_OK; }

  const std::string& display() const noexcept { return display_; }  // redacted()
  // The SQLSTATE of the last failed statement ("" after a success or a lost connection).
  const std::string& last_sqlstate() const noexcept { return last_sqlstate_; }
  PGconn* handle() const noexcept { return conn_; }
  // The failure of a statement whose result is `r` (null: no result at all).
  ArchiveFailure failure(const PGresult* r, std::string_view what);

 private:
  Connection(PGconn* conn, std::string conninfo);

  PGconn* conn_;
  std::string conninfo_;
  std::string display_;
  std::unordered_map<std::string, std::string> prepared_;  // SQL text -> statement name
  std::string last_sqlstate_;
};

// BEGIN ... COMMIT; ROLLBACK when left without commit(). Changes run READ COMMITTED with the
// station's row locked (pg_archive.cpp says why that is enough); reads run REPEATABLE READ
// READ ONLY, so every statement of one call sees one snapshot.
class Transaction {
 public:
  enum class Kind : std::uint8_t { kWrite, kRead };
  static Result<Transaction> begin(Connection& c, Kind kind);
  Transaction(Transaction&& other) noexcept : c_(other.c_) { other.c_ = nullptr; }
  Transaction& operator=(Transaction&&) = delete;
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  ~Transaction();
  Result<void> commit();

 private:
  explicit Transaction(Connection& c) : c_(&c) {}
  Connection* c_;
};

}  // namespace rs4sim::storage::pg
