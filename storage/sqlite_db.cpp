#include "storage/sqlite_db.h"

#include <utility>

namespace rs4sim::storage::sqlite {

ArchiveFailure error_from(int rc, sqlite3* db, std::string_view what) {
  ArchiveError code = ArchiveError::kIo;
  switch (rc & 0xFF) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED: code = ArchiveError::kBusy; break;
    case SQLITE_READONLY: code = ArchiveError::kReadOnly; break;
    case SQLITE_FULL: code = ArchiveError::kDiskFull; break;
    case SQLITE_NOTADB: code = ArchiveError::kNotAnArchive; break;
    case SQLITE_CORRUPT: code = ArchiveError::kCorruptArchive; break;
    default: break;
  }
  auto error = archive_error(code, what);
  error.message += " (";
  error.message += db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
  error.message += ")";
  return error;
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

void Statement::bind(int index, std::int64_t value) { sqlite3_bind_int64(stmt_, index, value); }

void Statement::bind(int index, std::string_view text) {
  // A default string_view has no data pointer, which SQLite would store as NULL.
  const char* data = text.data() != nullptr ? text.data() : "";
  sqlite3_bind_text64(stmt_, index, data, text.size(), SQLITE_TRANSIENT, SQLITE_UTF8);
}

void Statement::bind(int index, std::span<const std::uint8_t> blob) {
  // A zero-length blob is stored as an empty blob, not NULL.
  static constexpr std::uint8_t kEmpty = 0;
  const void* data = blob.empty() ? &kEmpty : blob.data();
  sqlite3_bind_blob64(stmt_, index, data, blob.size(), SQLITE_TRANSIENT);
}

void Statement::bind_null(int index) { sqlite3_bind_null(stmt_, index); }

void Statement::reset() noexcept {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

bool Statement::is_null(int column) const noexcept {
  return sqlite3_column_type(stmt_, column) == SQLITE_NULL;
}

std::string Statement::text(int column) const {
  const auto* p = sqlite3_column_text(stmt_, column);
  const auto n = sqlite3_column_bytes(stmt_, column);
  if (p == nullptr) return {};
  return {reinterpret_cast<const char*>(p), static_cast<std::size_t>(n)};
}

std::vector<std::uint8_t> Statement::blob(int column) const {
  const auto* p = static_cast<const std::uint8_t*>(sqlite3_column_blob(stmt_, column));
  const auto n = static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column));
  if (p == nullptr) return {};
  return {p, p + n};
}

Result<std::unique_ptr<Database>> Database::open(const std::string& path, int flags) {
  sqlite3* db = nullptr;
  const int rc = sqlite3_open_v2(path.c_str(), &db, flags | SQLITE_OPEN_NOMUTEX, nullptr);
  if (rc != SQLITE_OK) {
    auto err = error_from(rc, db, "sqlite3_open_v2");
    sqlite3_close_v2(db);
    return err;
  }
  sqlite3_extended_result_codes(db, 1);
  return std::unique_ptr<Database>(new Database(db, path));
}

Database::~Database() {
  cache_.clear();  // finalize every statement before closing
  sqlite3_close_v2(db_);
}

Result<StatementUse> Database::statement(std::string_view sql) {
  auto it = cache_.find(std::string(sql));
  if (it == cache_.end()) {
    sqlite3_stmt* stmt = nullptr;
    const int rc = sqlite3_prepare_v3(db_, sql.data(), static_cast<int>(sql.size()),
                                      SQLITE_PREPARE_PERSISTENT, &stmt, nullptr);
    if (rc != SQLITE_OK) return error(rc, "prepare");
    it = cache_.emplace(std::string(sql), std::make_unique<Statement>(stmt)).first;
  }
  return StatementUse(*it->second);
}

Result<void> Database::run(Statement& s, std::string_view what) {
  int rc = s.step();
  while (rc == SQLITE_ROW) rc = s.step();
  if (rc != SQLITE_DONE) return error(rc, what);
  return boost::outcome_v2::success();
}

Result<void> Database::exec(std::string_view sql) {
  BOOST_OUTCOME_TRY(s, statement(sql));
  return run(*s, sql);
}

Result<std::int64_t> Database::query_int(std::string_view sql) {
  BOOST_OUTCOME_TRY(s, statement(sql));
  const int rc = s->step();
  if (rc == SQLITE_ROW) return s->int64(0);
  if (rc == SQLITE_DONE) return std::int64_t{0};
  return error(rc, sql);
}

Result<Transaction> Transaction::begin(Database& db) {
  BOOST_OUTCOME_TRY(db.exec("BEGIN IMMEDIATE"));
  return Transaction(db);
}

Result<Transaction> Transaction::begin_read(Database& db) {
  BOOST_OUTCOME_TRY(db.exec("BEGIN"));
  return Transaction(db);
}

Transaction::~Transaction() {
  if (db_ != nullptr) (void)db_->exec("ROLLBACK");
}

Result<void> Transaction::commit() {
  BOOST_OUTCOME_TRY(db_->exec("COMMIT"));
  db_ = nullptr;
  return boost::outcome_v2::success();
}

}  // namespace rs4sim::storage::sqlite
