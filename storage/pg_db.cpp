#include "storage/pg_db.h"

#include <cstring>

namespace rs4sim::storage::pg {

using boost::outcome_v2::success;

namespace {

// Type OIDs of the columns Rows reads [PostgreSQL 15 source, src/include/catalog/pg_type.dat].
constexpr Oid kBoolOid = 16;
constexpr Oid kByteaOid = 17;
constexpr Oid kInt8Oid = 20;
constexpr Oid kInt2Oid = 21;
constexpr Oid kInt4Oid = 23;
constexpr Oid kTextOid = 25;
constexpr Oid kVarcharOid = 1043;

std::int64_t big_endian(const char* p, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) v = (v << 8U) | static_cast<unsigned char>(p[i]);
  // Sign-extend the 2- and 4-byte forms.
  const auto bits = static_cast<unsigned>(n) * 8U;
  if (bits < 64U && (v >> (bits - 1U)) != 0U) v |= ~std::uint64_t{0} << bits;
  return static_cast<std::int64_t>(v);
}

// libpq's multi-line messages ("connection to server ... failed: ...\n\tIs the server
// running ...?\n") on one line.
std::string one_line(const char* text) {
  std::string out;
  for (const char* p = text; p != nullptr && *p != '\0'; ++p) {
    if (*p == '\n' || *p == '\t') {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += *p;
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// The code of a SQLSTATE the archive distinguishes; kIo for the rest.
ArchiveError code_of(std::string_view state) {
  if (state == kSerializationFailure || state == kDeadlockDetected || state == "55P03") {
    return ArchiveError::kBusy;  // serialization failure, deadlock, lock not available
  }
  if (state == "25006" || state == "42501") return ArchiveError::kReadOnly;
  if (state == "53100") return ArchiveError::kDiskFull;
  if (state == "XX001" || state == "XX002" || state == "42P01" || state == "42703") {
    return ArchiveError::kCorruptArchive;  // data or index corrupted, a table or column gone
  }
  return ArchiveError::kIo;
}

void ignore_notice(void* /*arg*/, const char* /*message*/) {}

}  // namespace

bool is_postgres_uri(std::string_view location) noexcept {
  return location.starts_with("postgresql://") || location.starts_with("postgres://");
}

std::string redacted(std::string_view conninfo) {
  char* error = nullptr;
  const std::string text(conninfo);
  PQconninfoOption* options = PQconninfoParse(text.c_str(), &error);
  if (options == nullptr) {
    std::string reason = error != nullptr ? one_line(error) : "out of memory";
    PQfreemem(error);
    return "a connection string libpq cannot read (" + reason + ")";
  }
  std::string user;
  std::string host;
  std::string port;
  std::string dbname;
  for (const PQconninfoOption* o = options; o->keyword != nullptr; ++o) {
    if (o->val == nullptr) continue;
    const std::string_view key = o->keyword;
    if (key == "user") user = o->val;
    if (key == "host") host = o->val;
    if (key == "hostaddr" && host.empty()) host = o->val;
    if (key == "port") port = o->val;
    if (key == "dbname") dbname = o->val;
  }
  PQconninfoFree(options);
  std::string out = "postgresql://";
  if (!user.empty()) out += user + "@";
  out += host;
  if (!port.empty()) out += ":" + port;
  out += "/" + dbname;
  return out;
}

Params& Params::add(std::int64_t v) { return add(std::string_view(std::to_string(v))); }

Params& Params::add(std::string_view v) {
  storage_.emplace_back(v);
  null_.push_back(false);
  lengths_.push_back(static_cast<int>(v.size()));
  formats_.push_back(0);
  return *this;
}

Params& Params::add(std::span<const std::uint8_t> v) {
  storage_.emplace_back(reinterpret_cast<const char*>(v.data()), v.size());
  null_.push_back(false);
  lengths_.push_back(static_cast<int>(v.size()));
  formats_.push_back(1);
  return *this;
}

Params& Params::add_null() {
  storage_.emplace_back();
  null_.push_back(true);
  lengths_.push_back(0);
  formats_.push_back(0);
  return *this;
}

std::vector<const char*> Params::values() const {
  std::vector<const char*> out;
  out.reserve(storage_.size());
  for (std::size_t i = 0; i < storage_.size(); ++i) {
    out.push_back(null_[i] ? nullptr : storage_[i].data());
  }
  return out;
}

std::int64_t Rows::int64(int row, int col) const {
  const Oid type = PQftype(r_.get(), col);
  const int n = PQgetlength(r_.get(), row, col);
  const bool sized = (type == kInt8Oid && n == 8) || (type == kInt4Oid && n == 4) ||
                     (type == kInt2Oid && n == 2);
  if (!sized) return 0;  // NULL or a column the SQL did not cast (a bug the tests catch)
  return big_endian(PQgetvalue(r_.get(), row, col), n);
}

bool Rows::boolean(int row, int col) const {
  if (PQftype(r_.get(), col) != kBoolOid || PQgetlength(r_.get(), row, col) != 1) return false;
  return *PQgetvalue(r_.get(), row, col) != 0;
}

std::string Rows::text(int row, int col) const {
  const Oid type = PQftype(r_.get(), col);
  if (type != kTextOid && type != kVarcharOid) return {};
  return {PQgetvalue(r_.get(), row, col),
          static_cast<std::size_t>(PQgetlength(r_.get(), row, col))};
}

std::vector<std::uint8_t> Rows::bytes(int row, int col) const {
  if (PQftype(r_.get(), col) != kByteaOid) return {};
  const auto* p = reinterpret_cast<const std::uint8_t*>(PQgetvalue(r_.get(), row, col));
  return {p, p + PQgetlength(r_.get(), row, col)};
}

std::int64_t Rows::affected() const {
  const char* n = PQcmdTuples(r_.get());
  return n == nullptr || *n == '\0' ? 0 : std::strtoll(n, nullptr, 10);
}

Connection::Connection(PGconn* conn, std::string conninfo)
    : conn_(conn), conninfo_(std::move(conninfo)), display_(redacted(conninfo_)) {
  PQsetNoticeProcessor(conn_, &ignore_notice, nullptr);
}

Connection::~Connection() { PQfinish(conn_); }

Result<std::unique_ptr<Connection>> Connection::open(const std::string& conninfo) {
  // dbname is expanded as a whole connection string; the fallback name shows the archive in
  // pg_stat_activity unless the string names its own application_name.
  const char* keywords[] = {"dbname", "fallback_application_name", nullptr};
  const char* values[] = {conninfo.c_str(), "rs4sim", nullptr};
  PGconn* conn = PQconnectdbParams(keywords, values, 1);
  if (conn == nullptr) return archive_error(ArchiveError::kIo, "libpq: out of memory");
  if (PQstatus(conn) != CONNECTION_OK) {
    auto failure = archive_error(ArchiveError::kIo, "cannot connect");
    failure.message += " (" + one_line(PQerrorMessage(conn)) + ")";
    PQfinish(conn);
    return failure;
  }
  return std::unique_ptr<Connection>(new Connection(conn, conninfo));
}

ArchiveFailure Connection::failure(const PGresult* r, std::string_view what) {
  const char* state = r != nullptr ? PQresultErrorField(r, PG_DIAG_SQLSTATE) : nullptr;
  last_sqlstate_ = state != nullptr ? state : "";
  if (lost() || last_sqlstate_.starts_with("08") || last_sqlstate_.starts_with("57P")) {
    auto f = archive_error(ArchiveError::kIo, std::string(what) + ": connection to " +
                                                  display_ + " lost");
    f.message += " (" + one_line(PQerrorMessage(conn_)) + ")";
    return f;
  }
  const char* primary = r != nullptr ? PQresultErrorField(r, PG_DIAG_MESSAGE_PRIMARY) : nullptr;
  auto f = archive_error(code_of(last_sqlstate_), what);
  f.message += " (" + (primary != nullptr ? std::string(primary) : one_line(PQerrorMessage(conn_)));
  if (!last_sqlstate_.empty()) f.message += ", SQLSTATE " + last_sqlstate_;
  f.message += ")";
  return f;
}

Result<Rows> Connection::query(std::string_view sql, const Params& params, std::string_view what) {
  const std::string key(sql);
  auto it = prepared_.find(key);
  if (it == prepared_.end()) {
    const std::string name = "rs4sim_" + std::to_string(prepared_.size() + 1);
    // Parameter types come from the casts in the SQL ($1::int8).
    Rows prepared(PQprepare(conn_, name.c_str(), key.c_str(), 0, nullptr));
    if (PQresultStatus(prepared.raw()) != PGRES_COMMAND_OK) {
      return failure(prepared.raw(), what);
    }
    it = prepared_.emplace(key, name).first;
  }
  const auto values = params.values();
  Rows rows(PQexecPrepared(conn_, it->second.c_str(), params.size(), values.data(),
                           params.lengths(), params.formats(), 1));
  const auto status = PQresultStatus(rows.raw());
  if (status != PGRES_TUPLES_OK && status != PGRES_COMMAND_OK) return failure(rows.raw(), what);
  last_sqlstate_.clear();
  return rows;
}

Result<void> Connection::exec(std::string_view sql, std::string_view what) {
  Rows r(PQexec(conn_, std::string(sql).c_str()));
  const auto status = PQresultStatus(r.raw());
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) return failure(r.raw(), what);
  last_sqlstate_.clear();
  return success();
}

Result<void> Connection::reconnect_if_lost() {
  if (!lost()) return success();
  PQreset(conn_);
  prepared_.clear();  // a new backend knows none of them
  if (lost()) {
    auto f = archive_error(ArchiveError::kIo, "connection to " + display_ + " lost");
    f.message += ", reconnecting failed (" + one_line(PQerrorMessage(conn_)) + ")";
    return f;
  }
  PQsetNoticeProcessor(conn_, &ignore_notice, nullptr);
  return success();
}

Result<Transaction> Transaction::begin(Connection& c, Kind kind) {
  BOOST_OUTCOME_TRY(c.reconnect_if_lost());
  BOOST_OUTCOME_TRY(c.exec(kind == Kind::kWrite ? "BEGIN"
                                                : "BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY",
                           "begin transaction"));
  return Transaction(c);
}

Transaction::~Transaction() {
  if (c_ != nullptr && !c_->lost()) {
    PQclear(PQexec(c_->handle(), "ROLLBACK"));
  }
}

Result<void> Transaction::commit() {
  Connection* c = c_;
  c_ = nullptr;
  Rows r(PQexec(c->handle(), "COMMIT"));
  if (PQresultStatus(r.raw()) != PGRES_COMMAND_OK) return c->failure(r.raw(), "commit");
  // COMMIT of a transaction an error aborted answers ROLLBACK, not an error.
  if (std::string_view(PQcmdStatus(r.raw())) != "COMMIT") {
    return archive_error(ArchiveError::kIo, "commit: the server rolled the transaction back");
  }
  return success();
}

}  // namespace rs4sim::storage::pg
