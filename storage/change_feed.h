#pragma once
// The archive's change feed (docs/storage.md "Change feed"): every version as it is stored,
// by any master or workstation writing the same archive, so a second workstation sees a new
// version without asking. One feed owns its own connection(s) to the archive and blocks in
// next(); it belongs to one thread (the `archive watch` command, one streaming RPC call).
//
//   - SQLite: polls versions_after(last id seen). SQLite commits one writer at a time and
//     numbers ids in commit order, so polling with the last id misses nothing.
//   - PostgreSQL: LISTEN on kVersionChannel; every version insert queues a NOTIFY in its own
//     transaction (delivered at its commit, never for a rollback), and the feed reads the
//     notified ids. Ids are drawn before commit, so two writers can commit out of id order:
//     a poll by the last id would miss the lower one, the notifications do not.

#include "storage/errors.h"
#include "storage/types.h"

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::storage {

struct FeedOptions {
  // Versions with an id above this are delivered first; none: only versions stored from now.
  std::optional<VersionId> after;
  // SQLite: how often the file is asked (PostgreSQL is woken by the server instead).
  std::chrono::milliseconds poll_interval{100};
};

class ChangeFeed {
 public:
  virtual ~ChangeFeed() = default;
  // The versions stored since the last call, ascending by id; waits up to `timeout` for the
  // first one (empty when none came). Errors: the archive's (a lost server is reconnected on
  // the next call, the versions stored meanwhile read by id).
  virtual Result<std::vector<VersionInfo>> next(std::chrono::milliseconds timeout) = 0;

 protected:
  ChangeFeed() = default;
};

// `location` as open_archive() takes it; the feed opens the archive read-only.
Result<std::unique_ptr<ChangeFeed>> open_change_feed(const std::string& location,
                                                     const FeedOptions& options = {});

}  // namespace rs4sim::storage
