#include "storage/change_feed.h"

#include "storage/open_archive.h"
#include "storage/pg_archive.h"
#include "storage/pg_db.h"

#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <set>
#include <thread>

namespace rs4sim::storage {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kBatch = 1000;  // versions read per call at most

// ---- SQLite: poll by the last id seen (ids are committed in order).
class PollingFeed final : public ChangeFeed {
 public:
  PollingFeed(std::unique_ptr<ParameterArchive> archive, VersionId last,
              std::chrono::milliseconds poll)
      : archive_(std::move(archive)), last_(last), poll_(std::max(poll, std::chrono::milliseconds{1})) {}

  Result<std::vector<VersionInfo>> next(std::chrono::milliseconds timeout) override {
    const auto deadline = Clock::now() + timeout;
    for (;;) {
      BOOST_OUTCOME_TRY(found, archive_->versions_after(last_, kBatch));
      if (!found.empty()) {
        last_ = found.back().id;
        return found;
      }
      const auto left = deadline - Clock::now();
      if (left <= Clock::duration::zero()) return found;
      std::this_thread::sleep_for(std::min<Clock::duration>(left, poll_));
    }
  }

 private:
  std::unique_ptr<ParameterArchive> archive_;
  VersionId last_;
  std::chrono::milliseconds poll_;
};

// ---- PostgreSQL: LISTEN, and read what was notified.
class NotifiedFeed final : public ChangeFeed {
 public:
  static Result<std::unique_ptr<NotifiedFeed>> open(const std::string& location,
                                                    const FeedOptions& options) {
    PgOptions read_only;
    read_only.read_only = true;
    BOOST_OUTCOME_TRY(reader, PgArchive::open(location, read_only));
    BOOST_OUTCOME_TRY(listener, pg::Connection::open(location));
    std::unique_ptr<NotifiedFeed> feed(new NotifiedFeed(std::move(reader), std::move(listener)));
    BOOST_OUTCOME_TRY(feed->listen());
    // Listening before the start is read: a version committed in between is notified.
    if (options.after) {
      feed->last_ = *options.after;
      feed->catch_up_ = true;
    } else {
      BOOST_OUTCOME_TRY(newest, feed->reader_->newest_version_id());
      feed->last_ = newest;
    }
    return feed;
  }

  Result<std::vector<VersionInfo>> next(std::chrono::milliseconds timeout) override {
    if (listener_->lost()) {
      BOOST_OUTCOME_TRY(listener_->reconnect_if_lost());
      BOOST_OUTCOME_TRY(listen());
      catch_up_ = true;  // what was committed while the connection was down
    }
    std::vector<VersionInfo> out;
    if (catch_up_) {
      BOOST_OUTCOME_TRY(found, reader_->versions_after(last_, kBatch));
      catch_up_ = found.size() == kBatch;
      out = std::move(found);
    }
    BOOST_OUTCOME_TRY(consume());
    // The socket also wakes for what is not a notification (or another schema's): wait on
    // until one of ours came or the time is up.
    const auto deadline = Clock::now() + timeout;
    while (out.empty() && notified_.empty()) {
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) break;
      BOOST_OUTCOME_TRY(wait(left));
      BOOST_OUTCOME_TRY(consume());
    }
    if (!notified_.empty()) {
      const std::vector<VersionId> ids(notified_.begin(), notified_.end());
      notified_.clear();
      BOOST_OUTCOME_TRY(found, reader_->versions_by_id(ids));
      out.insert(out.end(), found.begin(), found.end());
    }
    std::sort(out.begin(), out.end(),
              [](const VersionInfo& a, const VersionInfo& b) { return a.id < b.id; });
    std::erase_if(out, [this](const VersionInfo& v) { return !delivered_.insert(v.id).second; });
    while (delivered_.size() > kRemembered) delivered_.erase(delivered_.begin());
    if (!out.empty()) last_ = std::max(last_, out.back().id);
    return out;
  }

 private:
  static constexpr std::size_t kRemembered = 100'000;  // ids kept to drop a repeat

  NotifiedFeed(std::unique_ptr<PgArchive> reader, std::unique_ptr<pg::Connection> listener)
      : reader_(std::move(reader)), listener_(std::move(listener)) {}

  Result<void> listen() {
    BOOST_OUTCOME_TRY(listener_->exec("LISTEN " + std::string(kVersionChannel), "listen"));
    BOOST_OUTCOME_TRY(r, listener_->query("SELECT current_schema()::text", "read the schema"));
    schema_ = r.is_null(0, 0) ? "" : r.text(0, 0);
    return boost::outcome_v2::success();
  }

  // Until a notification arrives on the listening connection or `timeout` passes.
  Result<void> wait(std::chrono::milliseconds timeout) {
    pollfd fd{PQsocket(listener_->handle()), POLLIN, 0};
    if (fd.fd < 0) return archive_error(ArchiveError::kIo, "connection to the archive lost");
    const int ms = static_cast<int>(std::min<std::int64_t>(timeout.count(), 24 * 3600 * 1000));
    if (::poll(&fd, 1, std::max(ms, 0)) < 0 && errno != EINTR) {
      return archive_error(ArchiveError::kIo, "wait for notifications failed");
    }
    return boost::outcome_v2::success();
  }

  // The notifications libpq has read, this archive's (its schema's) ids kept.
  Result<void> consume() {
    if (PQconsumeInput(listener_->handle()) == 0) {
      return archive_error(ArchiveError::kIo, "connection to " + listener_->display() + " lost");
    }
    while (PGnotify* n = PQnotifies(listener_->handle())) {
      const std::string_view payload(n->extra);
      const auto space = payload.rfind(' ');
      VersionId id = 0;
      if (space != std::string_view::npos && payload.substr(0, space) == schema_) {
        const auto digits = payload.substr(space + 1);
        const auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), id);
        if (ec == std::errc{} && p == digits.data() + digits.size()) notified_.insert(id);
      }
      PQfreemem(n);
    }
    return boost::outcome_v2::success();
  }

  std::unique_ptr<PgArchive> reader_;
  std::unique_ptr<pg::Connection> listener_;
  std::string schema_;
  VersionId last_ = 0;
  bool catch_up_ = false;
  std::set<VersionId> notified_;
  std::set<VersionId> delivered_;
};

}  // namespace

Result<std::unique_ptr<ChangeFeed>> open_change_feed(const std::string& location,
                                                     const FeedOptions& options) {
  return with_context("watch " + display_location(location),
                      [&]() -> Result<std::unique_ptr<ChangeFeed>> {
    if (is_server_location(location)) {
      BOOST_OUTCOME_TRY(feed, NotifiedFeed::open(location, options));
      return std::unique_ptr<ChangeFeed>(std::move(feed));
    }
    BOOST_OUTCOME_TRY(archive, open_archive(location, OpenOptions{true}));
    VersionId start = 0;
    if (options.after) {
      start = *options.after;
    } else {
      BOOST_OUTCOME_TRY(newest, archive->newest_version_id());
      start = newest;
    }
    return std::unique_ptr<ChangeFeed>(
        std::make_unique<PollingFeed>(std::move(archive), start, options.poll_interval));
  });
}

}  // namespace rs4sim::storage
