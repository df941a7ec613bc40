#include "rpc/archive_service.h"

#include "dp/pdu/sap.h"
#include "rpc/status.h"
#include "rs4/param_doc/field_coverage.h"
#include "rs4/report/field_svg.h"
#include "rs4/report/parameter_diff.h"
#include "rs4/report/parameter_summary.h"
#include "rs4/scanner/parameter_codec.h"
#include "storage/archive_file.h"
#include "storage/change_feed.h"
#include "storage/open_archive.h"
#include "storage/request_check.h"

#include <string>
#include <string_view>
#include <utility>

namespace rs4sim::rpc {
namespace {

void fill_key(const storage::StationKey& key, v1::StationKey& out) {
  out.set_bus(key.bus);
  out.set_address(key.address);
}

void fill_version(const storage::VersionInfo& v, v1::VersionInfo& out) {
  out.set_id(static_cast<std::uint64_t>(v.id));
  fill_key(v.station, *out.mutable_station());
  out.set_number(v.number);
  out.set_crc32(v.crc32);
  out.set_size(v.size);
  out.set_source(storage::to_string(v.source));
  out.set_stored_at_ms(v.at.time_since_epoch().count());
  out.set_note(v.note);
  out.set_restored_from(v.restored_from ? static_cast<std::uint64_t>(*v.restored_from) : 0U);
  out.set_pending_download(v.pending_download);
  out.set_serial_number(v.serial_number);
  out.set_user(v.user);
  out.set_host(v.host);
}

// "ipv4:127.0.0.1:51234" -> "127.0.0.1", "ipv6:[::1]:51234" -> "::1": the client's address.
std::string peer_host(const std::string& peer) {
  auto rest = peer.substr(peer.find(':') + 1);
  if (!rest.empty() && rest.front() == '[') return rest.substr(1, rest.find(']') - 1);
  const auto colon = rest.rfind(':');
  return colon == std::string::npos ? rest : rest.substr(0, colon);
}

// The request's station, or INVALID_ARGUMENT for an address above kMaxStationAddress.
void fill_import(const storage::ImportSummary& s, v1::ImportResponse& out) {
  const auto n = [](std::size_t v) { return static_cast<std::uint32_t>(v); };
  out.set_stations(n(s.stations));
  out.set_versions(n(s.versions));
  out.set_new_parameter_sets(n(s.new_sets));
  out.set_versions_present(n(s.versions_present));
  out.set_sync_log_entries(n(s.sync_log_entries));
  out.set_sync_log_present(n(s.sync_log_present));
  for (const auto& st : s.per_station) {
    auto& o = *out.add_per_station();
    fill_key(st.key, *o.mutable_station());
    o.set_versions_added(n(st.versions_added));
    o.set_versions_present(n(st.versions_present));
    o.set_current(storage::to_string(st.current));
    o.set_current_number(st.current_number);
  }
}

grpc::Status to_key(const v1::StationKey& in, storage::StationKey& out) {
  if (in.address() > dp::pdu::sap::kMaxStationAddress) {
    return invalid_argument("address", std::to_string(in.address()) + " outside 0.." +
                                           std::to_string(dp::pdu::sap::kMaxStationAddress));
  }
  out.bus = in.bus().empty() ? "default" : in.bus();
  out.address = static_cast<std::uint8_t>(in.address());
  return grpc::Status::OK;
}

grpc::Status to_id(std::uint64_t id, const std::string& field, storage::VersionId& out) {
  if (id == 0 || id > static_cast<std::uint64_t>(INT64_MAX)) {
    return invalid_argument(field, "a version id (the ID column of `rs4sim archive history`)");
  }
  out = static_cast<storage::VersionId>(id);
  return grpc::Status::OK;
}

// The decoded set of a version, or DATA_LOSS naming the version.
grpc::Status decode(const storage::VersionWithSet& v, rs4::scanner::ParameterSet& out) {
  auto set = rs4::scanner::decode_transfer_form(v.set.blob);
  if (!set) {
    return {grpc::StatusCode::DATA_LOSS,
            "version " + std::to_string(v.version.id) +
                " does not decode as an RS4 set: " + set.error().message()};
  }
  out = std::move(set).value();
  return grpc::Status::OK;
}

}  // namespace

grpc::Status archive_status(const storage::ArchiveFailure& failure, const std::string& field) {
  using storage::ArchiveError;
  const std::string& m = failure.message;
  switch (failure.code) {
    case ArchiveError::kUnknownStation:
    case ArchiveError::kUnknownVersion:
    case ArchiveError::kNotFound: return not_found(m);
    case ArchiveError::kInvalidArgument:
    case ArchiveError::kCorruptImport:
    case ArchiveError::kCrcMismatch: return invalid_argument(field, m);
    case ArchiveError::kBusy: return {grpc::StatusCode::UNAVAILABLE, m};
    case ArchiveError::kDiskFull: return {grpc::StatusCode::RESOURCE_EXHAUSTED, m};
    case ArchiveError::kReadOnly:
    case ArchiveError::kNotAnArchive:
    case ArchiveError::kNewerSchema: return failed_precondition("ARCHIVE", "archive", m);
    case ArchiveError::kCorruptArchive: return {grpc::StatusCode::DATA_LOSS, m};
    case ArchiveError::kIo: break;
  }
  return {grpc::StatusCode::INTERNAL, m};
}

grpc::Status ArchiveService::on_loop(const std::function<grpc::Status()>& f) {
  grpc::Status result;
  executor_.run([&] { result = f(); });
  return result;
}

grpc::Status ArchiveService::ListStations(grpc::ServerContext*, const v1::ListStationsRequest*,
                                          v1::ListStationsResponse* out) {
  out->set_archive(storage::display_location(location_));
  return on_loop([&] {
    auto stations = archive_.stations();
    if (!stations) return archive_status(stations.error(), "");
    for (const auto& s : stations.value()) {
      auto* o = out->add_stations();
      fill_key(s.key, *o->mutable_key());
      o->set_device_type(s.device_type);
      for (const auto& serial : s.serials) o->add_serial_numbers(serial.serial_number);
      o->set_current_version_id(s.current ? static_cast<std::uint64_t>(*s.current) : 0U);
      o->set_site(s.site);
      o->set_line(s.line);
    }
    return grpc::Status::OK;
  });
}

grpc::Status ArchiveService::History(grpc::ServerContext*, const v1::StationKey* in,
                                     v1::HistoryResponse* out) {
  storage::StationKey key;
  if (auto s = to_key(*in, key); !s.ok()) return s;
  return on_loop([&] {
    auto history = archive_.history(key);
    if (!history) return archive_status(history.error(), "address");
    for (const auto& v : history.value()) fill_version(v, *out->add_versions());
    return grpc::Status::OK;
  });
}

grpc::Status ArchiveService::GetVersion(grpc::ServerContext*, const v1::VersionRequest* in,
                                        v1::VersionDetail* out) {
  storage::VersionId id = 0;
  if (auto s = to_id(in->version_id(), "version_id", id); !s.ok()) return s;
  return on_loop([&] {
    auto v = archive_.get(id);
    if (!v) return archive_status(v.error(), "version_id");
    rs4::scanner::ParameterSet set;
    if (auto s = decode(v.value(), set); !s.ok()) return s;
    fill_version(v.value().version, *out->mutable_version());
    const auto& blob = v.value().set.blob;
    out->set_blob(std::string(blob.begin(), blob.end()));
    out->set_summary_json(rs4::report::summary_json(set));
    return grpc::Status::OK;
  });
}

grpc::Status ArchiveService::Diff(grpc::ServerContext*, const v1::DiffRequest* in,
                                  v1::DiffResponse* out) {
  storage::VersionId a = 0;
  storage::VersionId b = 0;
  if (auto s = to_id(in->old_version_id(), "old_version_id", a); !s.ok()) return s;
  if (auto s = to_id(in->new_version_id(), "new_version_id", b); !s.ok()) return s;
  return on_loop([&] {
    auto old_v = archive_.get(a);
    if (!old_v) return archive_status(old_v.error(), "old_version_id");
    auto new_v = archive_.get(b);
    if (!new_v) return archive_status(new_v.error(), "new_version_id");
    rs4::scanner::ParameterSet old_set;
    rs4::scanner::ParameterSet new_set;
    if (auto s = decode(old_v.value(), old_set); !s.ok()) return s;
    if (auto s = decode(new_v.value(), new_set); !s.ok()) return s;
    const auto d = rs4::report::diff(old_set, new_set);
    out->set_identical(d.empty());
    out->set_text(rs4::report::render_text(d));
    out->set_json(rs4::report::render_json(d));
    if (in->with_svg()) {
      const std::string old_label = "version " + std::to_string(a);
      const std::string new_label = "version " + std::to_string(b);
      const std::string title = "station " + old_v.value().version.station.bus + "/" +
                                std::to_string(old_v.value().version.station.address) + ", " +
                                old_label + " -> " + new_label;
      out->set_svg(rs4::report::field_diff_svg(old_set, new_set, {title, old_label, new_label}));
    }
    return grpc::Status::OK;
  });
}

grpc::Status ArchiveService::Restore(grpc::ServerContext* context, const v1::RestoreRequest* in,
                                     v1::VersionInfo* out) {
  storage::VersionId id = 0;
  if (auto s = to_id(in->version_id(), "version_id", id); !s.ok()) return s;
  const storage::Author by{in->user(),
                           in->host().empty() ? peer_host(context->peer()) : in->host()};
  // The texts by the field they came in (the archive's own refusal would name none).
  const std::pair<const char*, const std::string*> texts[] = {
      {"note", &in->note()}, {"user", &by.user}, {"host", &by.host}};
  for (const auto& [field, value] : texts) {
    const auto max = std::string_view(field) == "note" ? storage::kMaxNoteSize
                                                         : storage::kMaxNameSize;
    if (auto ok = storage::check_text(field, *value, max); !ok) {
      // invalid_argument names the field; the archive's text may start with it too
      std::string why = ok.error().message;
      if (const std::string head = std::string(field) + ": "; why.rfind(head, 0) == 0) {
        why.erase(0, head.size());
      }
      return invalid_argument(field, why);
    }
  }
  return on_loop([&] {
    auto old = archive_.get(id);
    if (!old) return archive_status(old.error(), "version_id");
    const rs4::param_doc::CoverageOptions coverage{in->allow_partial_field()};
    if (const auto issue = rs4::param_doc::check_stored_set(old.value().set.blob, coverage)) {
      return invalid_argument("allow_partial_field", issue->message());
    }
    auto v = archive_.restore(id, clock_(), in->note(), by);
    if (!v) return archive_status(v.error(), "version_id");
    fill_version(v.value(), *out);
    return grpc::Status::OK;
  });
}

grpc::Status ArchiveService::Export(grpc::ServerContext*, const v1::ExportRequest* in,
                                    v1::ExportResponse* out) {
  return on_loop([&] {
    if (in->format() == v1::EXPORT_FORMAT_JSON) {
      auto text = storage::export_json(archive_, clock_());
      if (!text) return archive_status(text.error(), "");
      out->set_file(std::move(text).value());
    } else {
      auto bytes = storage::export_binary(archive_, clock_());
      if (!bytes) return archive_status(bytes.error(), "");
      out->set_file(std::string(bytes.value().begin(), bytes.value().end()));
    }
    return grpc::Status::OK;
  });
}

grpc::Status ArchiveService::Import(grpc::ServerContext*, const v1::ImportRequest* in,
                                    v1::ImportResponse* out) {
  const auto& file = in->file();
  auto snap = in->format() == v1::EXPORT_FORMAT_JSON
                  ? storage::decode_json(file)
                  : storage::decode_binary(std::span(
                        reinterpret_cast<const std::uint8_t*>(file.data()), file.size()));
  if (!snap) return archive_status(snap.error(), "file");
  const rs4::param_doc::CoverageOptions coverage{in->allow_partial_field()};
  for (const auto* set : storage::current_sets(snap.value())) {
    if (const auto issue = rs4::param_doc::check_stored_set(set->blob, coverage)) {
      return invalid_argument("allow_partial_field", issue->message());
    }
  }
  return on_loop([&] {
    auto summary = archive_.import_snapshot(snap.value(), {in->make_current()});
    if (!summary) return archive_status(summary.error(), "file");
    fill_import(summary.value(), *out);
    return grpc::Status::OK;
  });
}

grpc::Status ArchiveService::Verify(grpc::ServerContext*, const v1::VerifyRequest*,
                                    v1::VerifyResponse* out) {
  return on_loop([&] {
    auto report = archive_.check_integrity();
    if (!report) return archive_status(report.error(), "");
    out->set_ok(report.value().ok());
    for (const auto& p : report.value().problems) out->add_problems(p);
    return grpc::Status::OK;
  });
}

grpc::Status ArchiveService::Note(grpc::ServerContext*, const v1::NoteRequest* in,
                                  v1::VersionInfo* out) {
  storage::VersionId id = 0;
  if (auto s = to_id(in->version_id(), "version_id", id); !s.ok()) return s;
  return on_loop([&] {
    auto v = archive_.annotate(id, in->note());
    if (!v) return archive_status(v.error(), v.error().code == storage::ArchiveError::kUnknownVersion
                                                 ? "version_id"
                                                 : "note");
    fill_version(v.value(), *out);
    return grpc::Status::OK;
  });
}

grpc::Status ArchiveService::WatchVersions(grpc::ServerContext* context,
                                           const v1::WatchVersionsRequest* in,
                                           grpc::ServerWriter<v1::VersionInfo>* writer) {
  if (location_.empty()) {
    return failed_precondition("ARCHIVE", "archive", "this run serves no archive location to watch");
  }
  if (in->has_after_id() && in->after_id() > static_cast<std::uint64_t>(INT64_MAX)) {
    return invalid_argument("after_id", "a version id (the ID column of `rs4sim archive history`)");
  }
  storage::FeedOptions options;
  if (in->has_after_id()) options.after = static_cast<storage::VersionId>(in->after_id());
  auto feed = storage::open_change_feed(location_, options);
  if (!feed) return archive_status(feed.error(), "");
  // Subscribed: the client may store now and see it (initial metadata marks the moment).
  writer->SendInitialMetadata();
  while (!closed_ && !context->IsCancelled()) {
    auto got = feed.value()->next(std::chrono::milliseconds{200});
    if (!got) return archive_status(got.error(), "");
    for (const auto& v : got.value()) {
      v1::VersionInfo item;
      fill_version(v, item);
      if (!writer->Write(item)) return grpc::Status::OK;  // the client has gone
    }
  }
  return grpc::Status::OK;
}

}  // namespace rs4sim::rpc
