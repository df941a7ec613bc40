// What only the PostgreSQL archive has (integration: the real server the ctest fixture started):
// connection failures that name the server and never the password, a database that is not an
// archive or is newer, a read-only session, the connection lost in the middle of a store, and
// masters creating the schema at once. The contract every engine shares is in
// archive_contract_test.cpp.
#include "storage/pg_archive.h"
#include "storage/pg_db.h"

#include "tests/storage/archive_engines.h"
#include "tests/storage/archive_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <thread>

namespace rs4sim::storage {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using testing::make_blob;
using testing::request;

const StationKey kStation{"bus1", 4};

TEST(PgRedacted, ShowsServerAndDatabaseButNeverThePassword) {
  EXPECT_EQ(pg::redacted("postgresql://plant:s3cret@db.example:5433/archive?sslmode=require"),
            "postgresql://plant@db.example:5433/archive");
  EXPECT_EQ(pg::redacted("host=db.example user=plant password=s3cret dbname=archive"),
            "postgresql://plant@db.example/archive");
  EXPECT_THAT(pg::redacted("postgresql://plant:s3cret@db.example/archive?bogus=1"),
              Not(HasSubstr("s3cret")));
  EXPECT_THAT(pg::redacted("host='unterminated password=s3cret"), Not(HasSubstr("s3cret")));
  EXPECT_TRUE(pg::is_postgres_uri("postgresql://x/y"));
  EXPECT_TRUE(pg::is_postgres_uri("postgres://x/y"));
  EXPECT_FALSE(pg::is_postgres_uri("archive.sqlite3"));
  EXPECT_FALSE(pg::is_postgres_uri("file://archive.sqlite3"));
}

class PgArchiveTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto uri = testing::postgres_uri();
    if (!uri) {
      if (testing::postgres_required()) FAIL() << "RS4SIM_REQUIRE_POSTGRES=1 but no server";
      GTEST_SKIP() << "no PostgreSQL server (tests/storage/postgres_server.sh)";
    }
    engine_ = std::make_unique<testing::PgEngine>(*uri);
    // "postgresql://rs4sim:PASSWORD@127.0.0.1:PORT/postgres"
    const auto& server = engine_->server();
    const auto colon = server.find(':', std::string("postgresql://").size());
    password_ = server.substr(colon + 1, server.find('@') - colon - 1);
  }
  std::string with(const std::string& from, const std::string& to) const {
    auto uri = engine_->location();
    uri.replace(uri.find(from), from.size(), to);
    return uri;
  }
  std::unique_ptr<testing::PgEngine> engine_;
  std::string password_;
};

TEST_F(PgArchiveTest, ConnectFailuresNameTheServerNeverThePassword) {
  const auto wrong_password = PgArchive::open(with(password_, "not-the-password"));
  ASSERT_TRUE(wrong_password.has_error());
  EXPECT_EQ(wrong_password.error().code, ArchiveError::kIo);
  EXPECT_THAT(wrong_password.error().message, HasSubstr("password authentication failed"));
  EXPECT_THAT(wrong_password.error().message, HasSubstr("open postgresql://rs4sim@127.0.0.1:"));
  EXPECT_THAT(wrong_password.error().message, Not(HasSubstr("not-the-password")));

  const auto wrong_database = PgArchive::open(with("/postgres?", "/no_such_db?"));
  ASSERT_TRUE(wrong_database.has_error());
  EXPECT_THAT(wrong_database.error().message, HasSubstr("\"no_such_db\" does not exist"));
  EXPECT_THAT(wrong_database.error().message, Not(HasSubstr(password_)));

  const auto port_start = engine_->server().rfind(':') + 1;
  const auto port = engine_->server().substr(port_start, engine_->server().find('/', port_start) -
                                                             port_start);
  const auto wrong_port = PgArchive::open(with(":" + port + "/", ":1/"));
  ASSERT_TRUE(wrong_port.has_error());
  EXPECT_THAT(wrong_port.error().message, HasSubstr("127.0.0.1:1/postgres"));
  EXPECT_THAT(wrong_port.error().message, HasSubstr("Connection refused"));
  EXPECT_THAT(wrong_port.error().message, Not(HasSubstr(password_)));
}

TEST_F(PgArchiveTest, ADatabaseOfSomethingElseIsRefusedAndLeftAsItIs) {
  engine_->raw().exec("CREATE TABLE " + engine_->schema() + ".orders (id int, item text)");
  engine_->raw().exec("INSERT INTO " + engine_->schema() + ".orders VALUES (1, 'x')");
  const auto before = engine_->digest();
  const auto opened = PgArchive::open(engine_->location());
  ASSERT_TRUE(opened.has_error());
  EXPECT_EQ(opened.error().code, ArchiveError::kNotAnArchive);
  EXPECT_THAT(opened.error().message,
              HasSubstr("holds 1 tables of something else (no rs4sim_archive table)"));
  EXPECT_EQ(engine_->digest(), before);
}

TEST_F(PgArchiveTest, ANewerSchemaIsRefusedAndLeftAsItIs) {
  PgArchive::open(engine_->location()).value()->store(request(kStation, make_blob(1))).value();
  engine_->raw().exec("UPDATE " + engine_->schema() + ".rs4sim_archive SET schema_version = 99");
  const auto before = engine_->digest();
  const auto opened = PgArchive::open(engine_->location());
  ASSERT_TRUE(opened.has_error());
  EXPECT_EQ(opened.error().code, ArchiveError::kNewerSchema);
  EXPECT_THAT(opened.error().message, HasSubstr("schema version 99, this rs4sim knows up to 5"));
  EXPECT_EQ(engine_->digest(), before);
}

TEST_F(PgArchiveTest, AReadOnlySessionReadsAndRefusesWrites) {
  PgOptions read_only;
  read_only.read_only = true;
  const auto empty = PgArchive::open(engine_->location(), read_only);
  ASSERT_TRUE(empty.has_error());
  EXPECT_EQ(empty.error().code, ArchiveError::kNotAnArchive);
  EXPECT_THAT(empty.error().message, HasSubstr("holds no archive yet"));

  const auto v = PgArchive::open(engine_->location()).value()->store(request(kStation, make_blob(1)));
  auto archive = PgArchive::open(engine_->location(), read_only).value();
  EXPECT_EQ(archive->current(kStation).value().version, v.value());
  const auto before = engine_->digest();
  const auto refused = archive->store(request(kStation, make_blob(2)));
  ASSERT_TRUE(refused.has_error());
  EXPECT_EQ(refused.error().code, ArchiveError::kReadOnly) << refused.error().message;
  EXPECT_EQ(engine_->digest(), before);
}

// The server ends the archive's connection while a store waits inside its transaction (for a
// row lock another session holds): the store fails naming the lost connection, nothing of it
// is stored, and the next store reconnects and works.
TEST_F(PgArchiveTest, AConnectionLostInTheMiddleOfAStoreRollsBackAndTheNextStoreWorks) {
  const std::string name = "rs4sim_lost_" + std::to_string(::getpid());
  auto archive = PgArchive::open(engine_->location() + "&application_name=" + name).value();
  archive->store(request(kStation, make_blob(1))).value();
  const auto before = engine_->digest();

  testing::RawPg locker(engine_->location());
  locker.exec("BEGIN");
  locker.exec("SELECT * FROM stations FOR UPDATE");
  std::optional<Result<VersionInfo>> result;
  std::thread store([&] { result = archive->store(request(kStation, make_blob(2))); });
  testing::RawPg admin(engine_->server());
  const auto waiting = "SELECT pid FROM pg_stat_activity WHERE application_name = '" + name +
                       "' AND wait_event_type = 'Lock'";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (admin.rows(waiting).empty() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));  // polls a state, times nothing
  }
  ASSERT_EQ(admin.rows("SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE "
                       "application_name = '" + name + "'")
                .size(),
            1u);
  store.join();
  locker.exec("ROLLBACK");

  ASSERT_TRUE(result && result->has_error());
  EXPECT_EQ(result->error().code, ArchiveError::kIo);
  EXPECT_THAT(result->error().message, HasSubstr("store station bus1/4"));
  EXPECT_THAT(result->error().message, HasSubstr("lost"));
  EXPECT_THAT(result->error().message, Not(HasSubstr(password_)));
  EXPECT_EQ(engine_->digest(), before);

  const auto next = archive->store(request(kStation, make_blob(3)));
  ASSERT_TRUE(next.has_value()) << next.error().message;
  EXPECT_EQ(next.value().number, 2u);
  EXPECT_EQ(archive->history(kStation).value().size(), 2u);
}

// Masters started at once against an empty database: one creates the schema, the others wait
// for it and find it current.
TEST_F(PgArchiveTest, MastersOpeningAnEmptyDatabaseAtOnceCreateTheSchemaOnce) {
  constexpr int kMasters = 4;
  std::vector<std::thread> masters;
  std::vector<std::string> errors(kMasters);
  for (int m = 0; m < kMasters; ++m) {
    masters.emplace_back([&, m] {
      auto opened = PgArchive::open(engine_->location());
      if (!opened) errors[static_cast<std::size_t>(m)] = opened.error().message;
    });
  }
  for (auto& t : masters) t.join();
  for (const auto& e : errors) EXPECT_EQ(e, "");
  EXPECT_EQ(engine_->raw().rows("SELECT application_id, schema_version FROM " +
                                engine_->schema() + ".rs4sim_archive"),
            (std::vector<std::vector<std::string>>{{"1381184577", "5"}}));
}

}  // namespace
}  // namespace rs4sim::storage
