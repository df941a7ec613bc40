#include "storage/archive_file.h"

#include "json/locate.h"
#include "json/message.h"
#include "rs4sim/v1/archive.pb.h"
#include "storage/time_ms.h"

#include <cctype>
#include <climits>

#include <google/protobuf/stubs/logging.h>
#include <google/protobuf/util/json_util.h>

#include <limits>

namespace rs4sim::storage {
namespace {

namespace pb = ::rs4sim::v1;
using boost::outcome_v2::success;

// google.protobuf.Timestamp's valid range: 0001-01-01T00:00:00Z .. 9999-12-31T23:59:59Z.
constexpr std::int64_t kMinSeconds = -62135596800;
constexpr std::int64_t kMaxSeconds = 253402300799;

void put_time(Timestamp t, google::protobuf::Timestamp& out) {
  const auto ms = to_ms(t);
  auto seconds = ms / 1000;
  auto rest = ms % 1000;
  if (rest < 0) {
    rest += 1000;
    --seconds;
  }
  out.set_seconds(seconds);
  out.set_nanos(static_cast<std::int32_t>(rest * 1'000'000));
}

Result<Timestamp> get_time(const google::protobuf::Timestamp& t, const char* what) {
  if (t.seconds() < kMinSeconds || t.seconds() > kMaxSeconds || t.nanos() < 0 ||
      t.nanos() > 999'999'999) {
    return archive_error(ArchiveError::kCorruptImport, std::string(what) + ": bad timestamp");
  }
  return from_ms(t.seconds() * 1000 + t.nanos() / 1'000'000);
}

void put_station(const SnapshotStation& in, pb::Station& out) {
  out.set_bus(in.key.bus);
  out.set_address(in.key.address);
  out.set_device_type(in.device_type);
  out.set_site(in.site);
  out.set_line(in.line);
  for (const auto& s : in.serials) {
    auto& o = *out.add_serial_numbers();
    o.set_serial_number(s.serial_number);
    put_time(s.first_seen, *o.mutable_first_seen());
    put_time(s.last_seen, *o.mutable_last_seen());
  }
  for (const auto& v : in.versions) {
    auto& o = *out.add_versions();
    o.set_number(v.number);
    o.set_parameter_set_id(static_cast<std::uint64_t>(v.set_id));
    put_time(v.at, *o.mutable_stored_at());
    o.set_source(static_cast<pb::VersionSource>(v.source));
    o.set_note(v.note);
    o.set_restored_from(v.restored_from);
    o.set_pending_download(v.pending_download);
    o.set_serial_number(v.serial_number);
    o.set_user(v.user);
    o.set_host(v.host);
    if (v.simulated) o.set_simulated_ms(v.simulated->count());
  }
  out.set_current_version(in.current_version);
  for (const auto& e : in.sync_log) {
    auto& o = *out.add_sync_log();
    put_time(e.at, *o.mutable_at());
    o.set_reason(e.reason);
    o.set_direction(static_cast<pb::SyncDirection>(e.direction));
    o.set_outcome(static_cast<pb::SyncOutcome>(e.outcome));
    o.set_error_number_fb(e.error_number_fb);
    o.set_error_code_sfc(e.error_code_sfc);
    o.set_error_number_device(e.error_number_device);
    o.set_duration_ms(static_cast<std::uint64_t>(e.duration.count()));
  }
}

pb::ArchiveExport to_proto(const Snapshot& snap) {
  pb::ArchiveExport out;
  out.set_format_version(snap.format_version);
  put_time(snap.exported_at, *out.mutable_exported_at());
  for (const auto& st : snap.stations) put_station(st, *out.add_stations());
  for (const auto& set : snap.sets) {
    auto& o = *out.add_parameter_sets();
    o.set_id(static_cast<std::uint64_t>(set.id));
    o.set_crc32(set.crc32);
    o.set_blob(set.blob.data(), set.blob.size());
    o.set_summary(set.summary);
  }
  return out;
}

Result<SnapshotVersion> get_version(const pb::Version& v) {
  SnapshotVersion out;
  out.number = v.number();
  if (v.parameter_set_id() > static_cast<std::uint64_t>(INT64_MAX)) {
    return archive_error(ArchiveError::kCorruptImport, "version: parameter set id too large");
  }
  out.set_id = static_cast<SetId>(v.parameter_set_id());
  BOOST_OUTCOME_TRY(at, get_time(v.stored_at(), "version"));
  out.at = at;
  out.source = static_cast<VersionSource>(v.source());
  out.note = v.note();
  out.restored_from = v.restored_from();
  out.pending_download = v.pending_download();
  out.serial_number = v.serial_number();
  out.user = v.user();
  out.host = v.host();
  if (v.has_simulated_ms()) out.simulated = std::chrono::milliseconds{v.simulated_ms()};
  return out;
}

Result<SyncLogEntry> get_sync(const pb::SyncLogEntry& e, const StationKey& key) {
  SyncLogEntry out;
  out.station = key;
  BOOST_OUTCOME_TRY(at, get_time(e.at(), "sync log entry"));
  out.at = at;
  out.reason = e.reason();
  out.direction = static_cast<SyncDirection>(e.direction());
  out.outcome = static_cast<SyncOutcome>(e.outcome());
  out.error_number_fb = e.error_number_fb();
  out.error_code_sfc = e.error_code_sfc();
  out.error_number_device = e.error_number_device();
  if (e.duration_ms() > static_cast<std::uint64_t>(INT64_MAX)) {
    return archive_error(ArchiveError::kCorruptImport, "sync log entry: duration too large");
  }
  out.duration = std::chrono::milliseconds{static_cast<std::int64_t>(e.duration_ms())};
  return out;
}

Result<SnapshotStation> get_station(const pb::Station& st) {
  if (st.address() > 126) {
    return archive_error(
        ArchiveError::kCorruptImport,
        "station " + json::cut(st.bus(), 64) + "/" + std::to_string(st.address()) +
            ": address above 126");
  }
  SnapshotStation out;
  out.key = StationKey{st.bus(), static_cast<std::uint8_t>(st.address())};
  out.device_type = st.device_type();
  out.site = st.site();
  out.line = st.line();
  for (const auto& s : st.serial_numbers()) {
    BOOST_OUTCOME_TRY(first, get_time(s.first_seen(), "serial number"));
    BOOST_OUTCOME_TRY(last, get_time(s.last_seen(), "serial number"));
    out.serials.push_back({s.serial_number(), first, last});
  }
  for (const auto& v : st.versions()) {
    BOOST_OUTCOME_TRY(version, get_version(v));
    out.versions.push_back(std::move(version));
  }
  out.current_version = st.current_version();
  for (const auto& e : st.sync_log()) {
    BOOST_OUTCOME_TRY(entry, get_sync(e, out.key));
    out.sync_log.push_back(std::move(entry));
  }
  return out;
}

Result<Snapshot> from_proto(const pb::ArchiveExport& in) {
  Snapshot out;
  out.format_version = in.format_version();
  BOOST_OUTCOME_TRY(exported, get_time(in.exported_at(), "exported_at"));
  out.exported_at = exported;
  for (const auto& st : in.stations()) {
    BOOST_OUTCOME_TRY(station, get_station(st));
    out.stations.push_back(std::move(station));
  }
  for (const auto& set : in.parameter_sets()) {
    if (set.id() > static_cast<std::uint64_t>(INT64_MAX)) {
      return archive_error(ArchiveError::kCorruptImport, "parameter set id too large");
    }
    const auto* data = reinterpret_cast<const std::uint8_t*>(set.blob().data());
    out.sets.push_back({static_cast<SetId>(set.id()),
                        set.crc32(),
                        {data, data + set.blob().size()},
                        set.summary()});
  }
  BOOST_OUTCOME_TRY(validate(out));
  return out;
}

}  // namespace

std::vector<std::uint8_t> encode_binary(const Snapshot& snapshot) {
  const auto text = to_proto(snapshot).SerializeAsString();
  return {text.begin(), text.end()};
}

std::string encode_json(const Snapshot& snapshot) {
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;
  std::string out;
  (void)google::protobuf::util::MessageToJsonString(to_proto(snapshot), &out, options);
  return out;
}

Result<Snapshot> decode_binary(std::span<const std::uint8_t> bytes) {
  pb::ArchiveExport message;
  const google::protobuf::LogSilencer quiet;  // a bad file is our error, not a log line
  if (bytes.size() > static_cast<std::size_t>(INT_MAX) ||
      !message.ParseFromArray(bytes.data(), static_cast<int>(bytes.size()))) {
    return archive_error(ArchiveError::kCorruptImport, "not a binary rs4sim.v1.ArchiveExport");
  }
  return from_proto(message);
}

// The member protobuf 3.21 names in a refusal: "(stations[0].bus): invalid value ..." names
// stations[0].bus, "(stations[0]) foo: Cannot find field." names stations[0].foo.
std::string named_member(std::string_view message) {
  if (message.empty() || message[0] != '(') return {};
  const auto close = message.find(')');
  if (close == std::string_view::npos) return {};
  std::string path(message.substr(1, close - 1));
  const auto rest = message.substr(close + 1);
  constexpr std::string_view kUnknown = ": Cannot find field.";
  if (rest.size() > kUnknown.size() + 1 && rest[0] == ' ' &&
      rest.substr(rest.size() - kUnknown.size()) == kUnknown) {
    path += (path.empty() ? "" : ".") + std::string(rest.substr(1, rest.size() - kUnknown.size() - 1));
  }
  return path;
}

// Why protobuf refused `text`, with the line and column where that is known: the structure
// scan's refusal carries them, a break of the grammar is found by json/syntax.h, and a member
// protobuf names by its path ("stations[0].versions[1].source") is found by json/path.h.
std::string json_refusal(std::string_view text, const google::protobuf::util::Status& status) {
  const auto said = status.message();
  const std::string message(said.data(), said.size());
  if (!message.empty() && std::isdigit(static_cast<unsigned char>(message[0]))) return message;
  if (const auto broken = json::first_syntax_error(text)) {
    return json::line_column(text, broken->offset) + ": " + broken->reason;
  }
  const auto member = named_member(message);
  if (const auto at = member.empty() ? std::nullopt : json::offset_of_member(text, member)) {
    return json::line_column(text, *at) + ": " + message;
  }
  return message;
}

Result<Snapshot> decode_json(std::string_view text) {
  pb::ArchiveExport message;
  google::protobuf::util::JsonParseOptions options;  // unknown fields are an error
  const google::protobuf::LogSilencer quiet;
  // The format has no array of arrays: protobuf 3.21 would read "stations": [[]] as none.
  json::StructureRules rules;
  rules.arrays_in_arrays = false;
  const auto status = json::to_message(text, message, options, rules);
  if (!status.ok()) {
    return archive_error(ArchiveError::kCorruptImport,
                         "not a JSON rs4sim.v1.ArchiveExport: " + json_refusal(text, status));
  }
  return from_proto(message);
}

Result<std::vector<std::uint8_t>> export_binary(ParameterArchive& archive, Timestamp at) {
  BOOST_OUTCOME_TRY(snap, archive.export_snapshot(at));
  return encode_binary(snap);
}

Result<std::string> export_json(ParameterArchive& archive, Timestamp at) {
  BOOST_OUTCOME_TRY(snap, archive.export_snapshot(at));
  return encode_json(snap);
}

Result<ImportSummary> import_binary(ParameterArchive& archive, std::span<const std::uint8_t> bytes,
                                   const ImportOptions& options) {
  auto snap = with_context("import", [&] { return decode_binary(bytes); });
  if (!snap) return std::move(snap).error();
  return archive.import_snapshot(snap.value(), options);  // adds its own "import: " context
}

Result<ImportSummary> import_json(ParameterArchive& archive, std::string_view text,
                                 const ImportOptions& options) {
  auto snap = with_context("import", [&] { return decode_json(text); });
  if (!snap) return std::move(snap).error();
  return archive.import_snapshot(snap.value(), options);  // adds its own "import: " context
}

}  // namespace rs4sim::storage
