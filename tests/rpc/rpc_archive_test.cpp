// The Archive service on a real gRPC server on loopback in front of a real SQLite archive.
// Known answers: the factory set's pair 2 protective field is 1500 mm (docs/rs4-scanner.md),
// so raising segments 100..140 to 1850 mm is "+350 mm" on exactly that range.
#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"
#include "http_front.h"
#include "rpc/archive_service.h"
#include "rpc/server.h"
#include "rpc_calls.h"
#include "rs4/report/field_svg.h"
#include "rs4/scanner/parameter_codec.h"
#include "rs4sim/v1/archive_service.grpc.pb.h"
#include "storage/crc32.h"
#include "storage/sqlite_archive.h"
#include "test_loop.h"
#include "tests/storage/archive_test_support.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <gtest/gtest.h>

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

#include <thread>

namespace rs4sim::rpc {
namespace {

const storage::StationKey kStation{"default", 4};

class RpcArchiveTest : public ::testing::Test, protected ServedLoop {
 protected:
  void SetUp() override {
    archive_ = storage::SqliteArchive::open(dir_.file("archive.sqlite3")).value();
    service_ = std::make_unique<ArchiveService>(
        *archive_, executor_, [] { return storage::testing::at_ms(5000); },
        dir_.file("archive.sqlite3").string());
    stub_ = serve<v1::Archive>(*service_);
  }
  void TearDown() override { stop_serving(); }
  storage::VersionId store(const rs4::scanner::ParameterSet& set, std::int64_t at) {
    const auto blob = rs4::scanner::encode(set);
    storage::StoreRequest r;
    r.station = kStation;
    r.device_type = "RS4/PROFIsafe";
    r.serial_number = "74565";
    r.blob = blob;
    r.crc32 = storage::crc32(blob);
    r.at = storage::testing::at_ms(at);
    return archive_->store(r).value().id;
  }

  storage::testing::TempDir dir_;
  std::unique_ptr<storage::SqliteArchive> archive_;
  std::unique_ptr<ArchiveService> service_;
  std::unique_ptr<v1::Archive::Stub> stub_;
};

// ListStations names the archive it shows (the master's page says which one); a PostgreSQL
// server without its password.
TEST_F(RpcArchiveTest, ListStationsNamesAServerArchiveWithoutItsPassword) {
  ArchiveService named(
      *archive_, executor_, [] { return storage::testing::at_ms(5000); },
      "postgresql://plant:s3cret@127.0.0.1:5433/rs4");
  v1::ListStationsResponse out;
  ASSERT_TRUE(named.ListStations(nullptr, nullptr, &out).ok());
  EXPECT_EQ(out.archive(), "postgresql://plant@127.0.0.1:5433/rs4");
}

TEST_F(RpcArchiveTest, HistoryDiffRestoreAndVerify) {
  const auto first = store(rs4::scanner::factory_default(), 1000);
  auto changed = rs4::scanner::factory_default();
  for (std::size_t n = 100; n <= 140; ++n) changed.pairs[1].protective_mm[n] = 1850;
  const auto second = store(changed, 2000);

  v1::ListStationsResponse stations;
  ASSERT_TRUE(
      unary(*stub_, &v1::Archive::Stub::ListStations, v1::ListStationsRequest{}, stations).ok());
  ASSERT_EQ(stations.stations_size(), 1);
  EXPECT_EQ(stations.stations(0).key().address(), 4U);
  EXPECT_EQ(stations.stations(0).current_version_id(), static_cast<std::uint64_t>(second));
  EXPECT_EQ(stations.archive(), dir_.file("archive.sqlite3").string());  // which archive

  v1::StationKey key;
  key.set_address(4);  // bus "" = "default"
  v1::HistoryResponse history;
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::History, key, history).ok());
  ASSERT_EQ(history.versions_size(), 2);
  EXPECT_EQ(history.versions(0).number(), 1U);
  EXPECT_EQ(history.versions(1).source(), "upload");
  EXPECT_EQ(history.versions(1).size(), 8507U);

  v1::DiffRequest d;
  d.set_old_version_id(static_cast<std::uint64_t>(first));
  d.set_new_version_id(static_cast<std::uint64_t>(second));
  v1::DiffResponse diff;
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::Diff, d, diff).ok());
  EXPECT_FALSE(diff.identical());
  EXPECT_EQ(diff.text(), "pair 2 protective: segments 100-140 changed, max +350 mm\n");
  EXPECT_EQ(diff.svg(), "") << "only with with_svg";
  {
    // The live view's picture: the one `rs4sim archive diff --svg` draws (rs4/report).
    grpc::ClientContext c;
    d.set_with_svg(true);
    v1::DiffResponse pictured;
    ASSERT_TRUE(stub_->Diff(&c, d, &pictured).ok());
    EXPECT_EQ(pictured.text(), diff.text());
    const std::string old_label = "version " + std::to_string(first);
    const std::string new_label = "version " + std::to_string(second);
    const std::string title = "station default/4, " + old_label + " -> " + new_label;
    EXPECT_NE(pictured.svg().find("<svg"), std::string::npos) << pictured.svg().substr(0, 80);
    EXPECT_NE(pictured.svg().find(rs4::report::xml_escape(title)), std::string::npos);
    EXPECT_EQ(pictured.svg(), rs4::report::field_diff_svg(rs4::scanner::factory_default(), changed,
                                                          {title, old_label, new_label}));
  }

  v1::VersionRequest g;
  g.set_version_id(static_cast<std::uint64_t>(first));
  v1::VersionDetail detail;
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::GetVersion, g, detail).ok());
  EXPECT_EQ(detail.blob().size(), 8507U);
  EXPECT_EQ(detail.summary_json().find("password"), std::string::npos);

  v1::RestoreRequest r;
  r.set_version_id(static_cast<std::uint64_t>(first));
  r.set_note("back to factory");
  v1::VersionInfo restored;
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::Restore, r, restored).ok());
  EXPECT_EQ(restored.number(), 3U);
  EXPECT_EQ(restored.source(), "restore");
  EXPECT_TRUE(restored.pending_download());
  EXPECT_EQ(restored.restored_from(), static_cast<std::uint64_t>(first));
  EXPECT_EQ(restored.stored_at_ms(), 5000);

  v1::VerifyResponse verify;
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::Verify, v1::VerifyRequest{}, verify).ok());
  EXPECT_TRUE(verify.ok());
}

TEST_F(RpcArchiveTest, ExportImportRoundTripAndRefusals) {
  store(rs4::scanner::factory_default(), 1000);
  v1::ExportRequest e;
  e.set_format(v1::EXPORT_FORMAT_JSON);
  v1::ExportResponse file;
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::Export, e, file).ok());
  EXPECT_NE(file.file().find("\"stations\""), std::string::npos);

  v1::ImportRequest i;
  i.set_format(v1::EXPORT_FORMAT_JSON);
  i.set_file(file.file());
  v1::ImportResponse imported;
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::Import, i, imported).ok());
  EXPECT_EQ(imported.stations(), 1U);
  EXPECT_EQ(imported.versions(), 0U);  // its own export: every version already there
  EXPECT_EQ(imported.versions_present(), 1U);
  EXPECT_EQ(imported.per_station(0).current(), "current unchanged");
  EXPECT_EQ(imported.new_parameter_sets(), 0U);  // deduplicated by content

  i.set_file("{ not json");
  const auto corrupt = unary(*stub_, &v1::Archive::Stub::Import, i, imported);
  EXPECT_EQ(corrupt.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(corrupt), "file");

  v1::VersionRequest g;
  g.set_version_id(999);
  v1::VersionDetail detail;
  EXPECT_EQ(unary(*stub_, &v1::Archive::Stub::GetVersion, g, detail).error_code(),
            grpc::StatusCode::NOT_FOUND);
  g.set_version_id(0);
  EXPECT_EQ(bad_field(unary(*stub_, &v1::Archive::Stub::GetVersion, g, detail)), "version_id");
  v1::StationKey key;
  key.set_address(200);
  v1::HistoryResponse history;
  EXPECT_EQ(bad_field(unary(*stub_, &v1::Archive::Stub::History, key, history)), "address");
  key.set_address(9);
  EXPECT_EQ(unary(*stub_, &v1::Archive::Stub::History, key, history).error_code(),
            grpc::StatusCode::NOT_FOUND);
  // The archive is unchanged by the refusals: one version (the import recognised it).
  EXPECT_EQ(archive_->history(kStation).value().size(), 1U);
}

TEST_F(RpcArchiveTest, NoteAndWhoRestored) {
  const auto first = store(rs4::scanner::factory_default(), 1000);
  v1::NoteRequest note;
  note.set_version_id(static_cast<std::uint64_t>(first));
  note.set_note("checked by QA");
  v1::VersionInfo out;
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::Note, note, out).ok());
  EXPECT_EQ(out.note(), "checked by QA");
  EXPECT_EQ(archive_->get(first).value().version.note, "checked by QA");

  // (A proto3 string is UTF-8 by definition: the client library refuses to send another.)
  note.set_note(std::string(4097, 'n'));
  const auto bad = unary(*stub_, &v1::Archive::Stub::Note, note, out);
  EXPECT_EQ(bad.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(bad), "note");
  EXPECT_NE(bad.error_message().find("note of 4097 bytes (at most 4096)"), std::string::npos);
  note.set_note("x");
  note.set_version_id(99);
  EXPECT_EQ(unary(*stub_, &v1::Archive::Stub::Note, note, out).error_code(),
            grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(archive_->get(first).value().version.note, "checked by QA");

  // Restore records the user the client names and, without a host, the client's address.
  v1::RestoreRequest restore;
  restore.set_version_id(static_cast<std::uint64_t>(first));
  restore.set_user("qa-engineer");
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::Restore, restore, out).ok());
  EXPECT_EQ(out.user(), "qa-engineer");
  EXPECT_EQ(out.host(), "127.0.0.1");
  restore.set_host("ws-maint-03");
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::Restore, restore, out).ok());
  EXPECT_EQ(out.host(), "ws-maint-03");

  // A bad note or user is blamed on that field, not on version_id (the id is fine).
  const auto restore_refusal = [&](const std::string& bad_note, const std::string& bad_user) {
    grpc::ClientContext c;
    v1::RestoreRequest r;
    r.set_version_id(static_cast<std::uint64_t>(first));
    r.set_note(bad_note);
    r.set_user(bad_user);
    v1::VersionInfo ignored;
    const auto s = stub_->Restore(&c, r, &ignored);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    return bad_field(s) + " | " + s.error_message();  // the field, then the message
  };
  const auto starts = [](const std::string& text, const std::string& head) {
    return text.rfind(head, 0) == 0;
  };
  const auto long_note = restore_refusal(std::string(4097, 'n'), "qa");
  EXPECT_TRUE(starts(long_note, "note | note: note of 4097 bytes (at most 4096)")) << long_note;
  const auto nul_user = restore_refusal("why", std::string("q\0a", 3));
  EXPECT_TRUE(starts(nul_user, "user | user: byte 1 is NUL")) << nul_user;
  const auto long_user = restore_refusal("why", std::string(257, 'u'));
  EXPECT_TRUE(starts(long_user, "user | user: user of 257 bytes (at most 256)")) << long_user;
}

// The change feed over gRPC: what another writer stores arrives on the stream; a call from an
// id replays the history first; the run's stop ends the call with OK, a client's cancel too.
TEST_F(RpcArchiveTest, WatchVersionsStreamsWhatAnotherWriterStores) {
  const auto first = store(rs4::scanner::factory_default(), 1000);
  grpc::ClientContext live;
  auto stream = stub_->WatchVersions(&live, v1::WatchVersionsRequest{});
  stream->WaitForInitialMetadata();  // subscribed: a version stored from now is new to it
  auto writer = storage::SqliteArchive::open(dir_.file("archive.sqlite3")).value();
  const auto blob = rs4::scanner::encode(rs4::scanner::factory_default());
  storage::StoreRequest r;
  r.station = {"line2", 7};
  r.blob = blob;
  r.crc32 = storage::crc32(blob);
  r.user = "master-2";
  r.at = storage::testing::at_ms(2000);
  const auto second = writer->store(r).value();
  v1::VersionInfo item;
  ASSERT_TRUE(stream->Read(&item));
  EXPECT_EQ(item.id(), static_cast<std::uint64_t>(second.id));
  EXPECT_EQ(item.station().bus(), "line2");
  EXPECT_EQ(item.user(), "master-2");

  grpc::ClientContext replay;
  v1::WatchVersionsRequest from_start;
  from_start.set_after_id(0);
  auto all = stub_->WatchVersions(&replay, from_start);
  ASSERT_TRUE(all->Read(&item));
  EXPECT_EQ(item.id(), static_cast<std::uint64_t>(first));
  ASSERT_TRUE(all->Read(&item));
  EXPECT_EQ(item.id(), static_cast<std::uint64_t>(second.id));
  replay.TryCancel();
  EXPECT_EQ(all->Finish().error_code(), grpc::StatusCode::CANCELLED);

  service_->close_streams();
  EXPECT_FALSE(stream->Read(&item));
  EXPECT_TRUE(stream->Finish().ok());
}

TEST_F(RpcArchiveTest, WatchVersionsWithoutALocationIsRefused) {
  ArchiveService no_location(*archive_, executor_, [] { return storage::testing::at_ms(0); });
  RpcServer server(ServerOptions{}, std::vector<grpc::Service*>{&no_location});
  auto stub = v1::Archive::NewStub(
      grpc::CreateChannel(server.address(), grpc::InsecureChannelCredentials()));
  grpc::ClientContext c;
  auto stream = stub->WatchVersions(&c, v1::WatchVersionsRequest{});
  v1::VersionInfo item;
  EXPECT_FALSE(stream->Read(&item));
  const auto status = stream->Finish();
  EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(status.error_message().find("no archive location"), std::string::npos);
  server.shutdown();
}

// The same service as JSON over HTTP (docs/http.md).
TEST_F(RpcArchiveTest, JsonOverHttpIsTheSameService) {
  const auto id = store(rs4::scanner::factory_default(), 1000);
  HttpFront h(io_, *server_);
  const auto got = h.call("rs4sim.v1.Archive/ListStations");
  ASSERT_EQ(got.status, 200u) << got.body;
  const auto stations = from_json<v1::ListStationsResponse>(got.body);
  ASSERT_EQ(stations.stations_size(), 1);
  EXPECT_EQ(stations.stations(0).key().address(), 4U);
  EXPECT_EQ(stations.stations(0).current_version_id(), static_cast<std::uint64_t>(id));
  // uint64 fields are strings in protobuf's JSON mapping
  EXPECT_NE(got.body.find("\"currentVersionId\":\"" + std::to_string(id) + "\""), std::string::npos)
      << got.body;
}

// A stored RS4 set whose protective field has segments of 0 mm is not made current by a
// restore unless allow_partial_field says it on purpose (rs4/param_doc/field_coverage.h).
TEST_F(RpcArchiveTest, RestoreOfAPartialProtectiveFieldNeedsAllowPartialField) {
  auto partial = rs4::scanner::factory_default();
  for (std::size_t n = 0; n < 488; ++n) partial.pairs[1].protective_mm[n] = 0;
  const auto old = store(partial, 1000);
  store(rs4::scanner::factory_default(), 2000);
  v1::RestoreRequest r;
  r.set_version_id(static_cast<std::uint64_t>(old));
  v1::VersionInfo restored;
  const auto refused = unary(*stub_, &v1::Archive::Stub::Restore, r, restored);
  EXPECT_EQ(refused.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(refused), "allow_partial_field");
  EXPECT_NE(refused.error_message().find("field pair 2: 488 of 529"), std::string::npos)
      << refused.error_message();
  EXPECT_EQ(archive_->history(kStation).value().size(), 2u);
  r.set_allow_partial_field(true);
  ASSERT_TRUE(unary(*stub_, &v1::Archive::Stub::Restore, r, restored).ok());
  EXPECT_TRUE(restored.pending_download());
}

}  // namespace
}  // namespace rs4sim::rpc
