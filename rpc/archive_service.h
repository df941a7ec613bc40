#pragma once
// The Archive service of rs4sim.v1 (docs/rpc.md "Archive"): the parameter archive over
// gRPC, as `rs4sim archive` offers it on the command line. The archive belongs to the
// loop thread (an archive is one connection, not thread-safe): every call runs there.

#include "rpc/executor.h"
#include "rs4sim/v1/archive_service.grpc.pb.h"
#include "storage/parameter_archive.h"

#include <atomic>
#include <functional>
#include <string>

namespace rs4sim::rpc {

// grpc status for an archive failure, with its message: NOT_FOUND (unknown station or
// version, no current set), INVALID_ARGUMENT (bad request, corrupt import, CRC mismatch),
// UNAVAILABLE (locked), RESOURCE_EXHAUSTED (disk full), FAILED_PRECONDITION (read-only,
// not an archive, newer schema), DATA_LOSS (corrupt archive), INTERNAL (I/O).
grpc::Status archive_status(const storage::ArchiveFailure& failure, const std::string& field);

class ArchiveService final : public v1::Archive::Service {
 public:
  using Clock = std::function<storage::Timestamp()>;
  // `location` (what --archive named) lets WatchVersions open its own change feed (one per
  // call, on the call's thread: the feed blocks, the loop must not); "" refuses it.
  ArchiveService(storage::ParameterArchive& archive, Executor& executor, Clock clock,
                 std::string location = {})
      : archive_(archive),
        executor_(executor),
        clock_(std::move(clock)),
        location_(std::move(location)) {}

  grpc::Status ListStations(grpc::ServerContext*, const v1::ListStationsRequest*,
                            v1::ListStationsResponse* out) override;
  grpc::Status History(grpc::ServerContext*, const v1::StationKey* in,
                       v1::HistoryResponse* out) override;
  grpc::Status GetVersion(grpc::ServerContext*, const v1::VersionRequest* in,
                          v1::VersionDetail* out) override;
  grpc::Status Diff(grpc::ServerContext*, const v1::DiffRequest* in,
                    v1::DiffResponse* out) override;
  grpc::Status Restore(grpc::ServerContext*, const v1::RestoreRequest* in,
                       v1::VersionInfo* out) override;
  grpc::Status Export(grpc::ServerContext*, const v1::ExportRequest* in,
                      v1::ExportResponse* out) override;
  grpc::Status Import(grpc::ServerContext*, const v1::ImportRequest* in,
                      v1::ImportResponse* out) override;
  grpc::Status Verify(grpc::ServerContext*, const v1::VerifyRequest*,
                      v1::VerifyResponse* out) override;
  grpc::Status Note(grpc::ServerContext*, const v1::NoteRequest* in,
                    v1::VersionInfo* out) override;
  grpc::Status WatchVersions(grpc::ServerContext* context, const v1::WatchVersionsRequest* in,
                             grpc::ServerWriter<v1::VersionInfo>* writer) override;
  // Ends every WatchVersions call within one poll (the run's ordered stop, before the server's
  // shutdown waits for its calls).
  void close_streams() noexcept { closed_ = true; }

 private:
  // Runs `f` on the loop; its status is the call's.
  grpc::Status on_loop(const std::function<grpc::Status()>& f);

  storage::ParameterArchive& archive_;
  Executor& executor_;
  Clock clock_;
  std::string location_;
  std::atomic<bool> closed_{false};
};

}  // namespace rs4sim::rpc
