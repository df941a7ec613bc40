// The change feed (storage/change_feed.h) on both engines: versions stored by another writer
// arrive in id order, a feed from an id replays what came after it, the wait ends at its
// timeout; on PostgreSQL a version committed after a higher id (two masters whose
// transactions overlap) is still delivered, and another schema's versions are not.
#include "storage/change_feed.h"

#include "tests/storage/archive_engines.h"
#include "tests/storage/archive_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <thread>

namespace rs4sim::storage {
namespace {

using namespace std::chrono_literals;
using testing::make_blob;
using testing::request;

const StationKey kStation{"line1", 4};
const StationKey kOther{"line2", 4};

// What the feed delivers within `deadline`, until `count` versions came.
std::vector<VersionInfo> collect(ChangeFeed& feed, std::size_t count,
                                 std::chrono::milliseconds deadline = 10s) {
  std::vector<VersionInfo> out;
  const auto until = std::chrono::steady_clock::now() + deadline;
  while (out.size() < count && std::chrono::steady_clock::now() < until) {
    auto got = feed.next(200ms);
    if (!got) {
      ADD_FAILURE() << got.error().message;
      break;
    }
    out.insert(out.end(), got.value().begin(), got.value().end());
  }
  return out;
}

std::string feed_engine_name(const ::testing::TestParamInfo<std::string>& p) { return p.param; }

class ChangeFeedTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    engine_ = testing::make_engine(GetParam());
    if (!engine_) GTEST_SKIP() << "no PostgreSQL server (tests/storage/postgres_server.sh)";
    archive_ = engine_->open();  // creates the schema
  }
  std::unique_ptr<ChangeFeed> feed(std::optional<VersionId> after = std::nullopt) {
    FeedOptions options;
    options.after = after;
    options.poll_interval = 10ms;
    auto opened = open_change_feed(engine_->location(), options);
    if (!opened) throw std::runtime_error(opened.error().message);
    return std::move(opened).value();
  }
  std::unique_ptr<testing::Engine> engine_;
  std::unique_ptr<ParameterArchive> archive_;
};

INSTANTIATE_TEST_SUITE_P(Engines, ChangeFeedTest, ::testing::Values("sqlite", "postgresql"),
                         feed_engine_name);

TEST_P(ChangeFeedTest, VersionsStoredByAnotherWriterArriveInIdOrder) {
  const auto before = archive_->store(request(kStation, make_blob(1), 1000)).value();
  auto f = feed();  // from now: the version stored before is not delivered
  auto writer = engine_->open();
  const auto a = writer->store(request(kStation, make_blob(2), 2000)).value();
  const auto b = writer->store(request(kOther, make_blob(3), 3000)).value();
  const auto c = writer->restore(before.id, testing::at_ms(4000), "undo").value();
  EXPECT_EQ(collect(*f, 3), (std::vector<VersionInfo>{a, b, c}));
  EXPECT_TRUE(f->next(50ms).value().empty());  // each delivered once
}

TEST_P(ChangeFeedTest, AFeedFromAnIdDeliversWhatCameAfterItFirst) {
  const auto v1 = archive_->store(request(kStation, make_blob(1), 1000)).value();
  const auto v2 = archive_->store(request(kStation, make_blob(2), 2000)).value();
  const auto v3 = archive_->store(request(kOther, make_blob(3), 3000)).value();
  auto f = feed(v1.id);
  EXPECT_EQ(collect(*f, 2), (std::vector<VersionInfo>{v2, v3}));
  const auto v4 = archive_->store(request(kOther, make_blob(4), 4000)).value();
  EXPECT_EQ(collect(*f, 1), (std::vector<VersionInfo>{v4}));
}

// Both sides of the wait: not before the timeout, and it does come back.
TEST_P(ChangeFeedTest, NextWithNothingStoredReturnsEmptyAfterItsTimeout) {
  auto f = feed();
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(f->next(150ms).value().empty());
  const auto waited = std::chrono::steady_clock::now() - start;
  EXPECT_GE(waited, 150ms);
  EXPECT_LT(waited, 5s);
}

TEST(ChangeFeedSqlite, AMissingFileIsAnErrorNamingIt) {
  testing::TempDir dir;
  const auto path = dir.file("nowhere.sqlite3").string();
  const auto opened = open_change_feed(path);
  ASSERT_TRUE(opened.has_error());
  EXPECT_THAT(opened.error().message, ::testing::HasSubstr("watch " + path));
}

class PgChangeFeed : public ChangeFeedTest {};
INSTANTIATE_TEST_SUITE_P(Engines, PgChangeFeed, ::testing::Values("postgresql"),
                         feed_engine_name);

// Two masters whose transactions overlap: the first draws the lower id and commits last (here
// held by a lock on the station's current-version row, as a slow commit would). A feed that
// polled by the last id it saw would skip it; the notified feed delivers it.
TEST_P(PgChangeFeed, AVersionCommittedAfterAHigherIdIsStillDelivered) {
  archive_->store(request(kStation, make_blob(1), 1000)).value();
  archive_->store(request(kOther, make_blob(2), 2000)).value();
  auto* pg = dynamic_cast<testing::PgEngine*>(engine_.get());
  ASSERT_NE(pg, nullptr);
  auto f = feed();
  testing::RawPg blocker(pg->location());
  blocker.exec("BEGIN");
  blocker.exec("SELECT c.version_id FROM current_versions c JOIN stations s ON s.id = "
               "c.station_id WHERE s.bus = 'line1' FOR UPDATE OF c");
  std::optional<VersionInfo> slow;
  std::thread first([&] {
    auto writer = engine_->open();
    const auto blob = make_blob(3);
    slow = writer->store(request(kStation, blob, 3000)).value();
  });
  // The first writer has drawn its id and waits for the row lock.
  for (int i = 0; i < 500; ++i) {
    if (pg->raw().rows("SELECT count(*) FROM pg_locks WHERE NOT granted")[0][0] != "0") break;
    std::this_thread::sleep_for(10ms);
  }
  ASSERT_NE(pg->raw().rows("SELECT count(*) FROM pg_locks WHERE NOT granted")[0][0], "0");
  const auto fast = archive_->store(request(kOther, make_blob(4), 4000)).value();
  const auto seen_first = collect(*f, 1);
  ASSERT_EQ(seen_first, (std::vector<VersionInfo>{fast}));
  blocker.exec("COMMIT");
  first.join();
  ASSERT_TRUE(slow.has_value());
  EXPECT_LT(slow->id, fast.id);  // drawn before, committed after
  EXPECT_EQ(collect(*f, 1), (std::vector<VersionInfo>{*slow}));
  EXPECT_EQ(archive_->versions_after(fast.id, 10).value().size(), 0u);  // what polling would see
}

TEST_P(PgChangeFeed, AnotherSchemasVersionsAreNotDelivered) {
  auto f = feed();
  const auto neighbour = testing::make_engine("postgresql");
  ASSERT_NE(neighbour, nullptr);
  neighbour->open()->store(request(kStation, make_blob(1), 1000)).value();
  EXPECT_TRUE(f->next(300ms).value().empty());
  const auto mine = archive_->store(request(kStation, make_blob(2), 2000)).value();
  EXPECT_EQ(collect(*f, 1), (std::vector<VersionInfo>{mine}));
}

}  // namespace
}  // namespace rs4sim::storage
