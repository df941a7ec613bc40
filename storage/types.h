#pragma once
// The archive's data model, as plain values (docs/storage.md "Data model"). The archive
// knows nothing of any device: a parameter set is an opaque byte string with metadata
// the caller provides (device type, serial number, CRC-32, a decoded summary).

#include <chrono>
#include <compare>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rs4sim::storage {

// Instants are passed in by the caller (the archive reads no clock); stored as Unix ms.
using Timestamp = std::chrono::sys_time<std::chrono::milliseconds>;
using VersionId = std::int64_t;  // archive-wide id of one version row
using SetId = std::int64_t;      // archive-wide id of one distinct parameter set

struct StationKey {
  std::string bus;          // the caller's bus name
  std::uint8_t address{0};  // 0..126
  auto operator<=>(const StationKey&) const = default;
};

enum class VersionSource : std::uint8_t { kUpload = 1, kDownload, kImport, kRestore };
// "upload", "download", "import", "restore" ("unknown" for a value outside the enum).
[[nodiscard]] const char* to_string(VersionSource s) noexcept;
enum class SyncDirection : std::uint8_t { kNone = 1, kUpload, kDownload, kVerify };
enum class SyncOutcome : std::uint8_t { kSucceeded = 1, kFailed, kAborted };

// Who made a change, recorded with the version (docs/storage.md "What maintenance records").
struct Author {
  std::string user;
  std::string host;
};

// One store() call: the set the caller has, for one station.
struct StoreRequest {
  StationKey station;
  std::string device_type;
  std::string serial_number;
  std::span<const std::uint8_t> blob;
  std::uint32_t crc32{0};  // the caller's CRC-32/ISO-HDLC claim, checked
  std::string summary;     // decoded summary (text or JSON), stored as given
  VersionSource source{VersionSource::kUpload};
  // When it was written: the wall clock at the write, never later (docs/storage.md "Times").
  Timestamp at{};
  // A simulated run's own time at the write (its clock since the run's zero), recorded beside
  // `at`; none for a real device's set.
  std::optional<std::chrono::milliseconds> simulated;
  std::string note;     // the comment: why this version exists (a user's words, the proxy's scenario)
  std::string user;     // who stored it (the OS user unless given)
  std::string host;     // from which computer
  // The station's place in the plant, above the bus (docs/storage.md "What maintenance
  // records"): recorded when not empty, kept otherwise.
  std::string site;
  std::string line;
  // Store nothing when the station's current version has these bytes: store() then returns
  // that version unchanged (the serial number is still recorded as seen).
  bool skip_identical{false};
};

struct ParameterSetRecord {
  SetId id{0};
  std::uint32_t crc32{0};
  std::vector<std::uint8_t> blob;
  std::string summary;
  bool operator==(const ParameterSetRecord&) const = default;
};

struct VersionInfo {
  VersionId id{0};
  StationKey station;
  std::uint32_t number{0};  // 1, 2, 3 ... per station
  SetId set_id{0};
  std::uint32_t crc32{0};
  std::uint32_t size{0};
  VersionSource source{VersionSource::kUpload};
  Timestamp at{};
  std::optional<std::chrono::milliseconds> simulated;  // StoreRequest::simulated
  std::string note;
  std::optional<VersionId> restored_from;
  bool pending_download{false};
  std::string serial_number;
  std::string user;
  std::string host;
  bool operator==(const VersionInfo&) const = default;
};

struct VersionWithSet {
  VersionInfo version;
  ParameterSetRecord set;
};

struct SerialSeen {
  std::string serial_number;
  Timestamp first_seen{};
  Timestamp last_seen{};
  bool operator==(const SerialSeen&) const = default;
};

struct StationInfo {
  StationKey key;
  std::string device_type;
  std::string site;  // "" when never given
  std::string line;
  std::vector<SerialSeen> serials;  // in order of first appearance
  std::optional<VersionId> current;
};

struct SyncLogEntry {
  StationKey station;
  Timestamp at{};
  std::string reason;
  SyncDirection direction{SyncDirection::kNone};
  SyncOutcome outcome{SyncOutcome::kSucceeded};
  std::uint32_t error_number_fb{0};
  std::uint32_t error_code_sfc{0};
  std::uint32_t error_number_device{0};
  std::chrono::milliseconds duration{0};
  bool operator==(const SyncLogEntry&) const = default;
};

struct IntegrityReport {
  std::vector<std::string> problems;  // empty: the archive is sound
  bool ok() const { return problems.empty(); }
};

}  // namespace rs4sim::storage
