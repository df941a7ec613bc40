#pragma once
// Errors of the parameter archive: an enum class in its own std::error_category, and
// ArchiveFailure, which adds the context a user needs (which station, version or file).
// Every operation returns Result<T>; on any error the archive is unchanged.

#include "codec/error_category.h"

#include <boost/outcome/std_result.hpp>
#include <boost/outcome/try.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

namespace rs4sim::storage {

enum class ArchiveError : std::uint8_t {
  kUnknownStation = 1,  // no station with that bus/address
  kUnknownVersion,      // no version with that id
  kNotFound,            // a station without a current set, an empty result
  kNotAnArchive,        // not a SQLite file, or a SQLite file that is not ours
  kNewerSchema,         // written by a newer rs4sim (PRAGMA user_version too high)
  kCorruptImport,       // import file malformed or inconsistent
  kCrcMismatch,         // a blob's CRC-32 differs from the one claimed or stored
  kInvalidArgument,     // a request the archive cannot store (empty blob, bad address)
  kBusy,                // another connection holds the lock (SQLITE_BUSY/LOCKED)
  kReadOnly,            // the file or connection is read-only
  kDiskFull,            // SQLITE_FULL: disk or max_page_count reached
  kCorruptArchive,      // SQLITE_CORRUPT, or an integrity check found a problem
  kIo,                  // cannot open, I/O error, or any other SQLite failure
};

[[nodiscard]] std::string_view to_string(ArchiveError e) noexcept;
constexpr const char* error_category_name(ArchiveError) noexcept { return "rs4sim.archive"; }
inline std::error_code make_error_code(ArchiveError e) noexcept {
  return codec::make_error_code_of(e);
}
inline const std::error_category& archive_category() noexcept {
  return codec::category_of<ArchiveError>();
}

// The code plus a message naming the operation and its object.
struct ArchiveFailure {
  ArchiveError code{ArchiveError::kIo};
  std::string message;  // e.g. "store station bus1/4: disk full (database or disk is full)"
};

// Lets Result<T>::value() throw std::system_error when misused (outcome's default policy).
std::error_code make_error_code(const ArchiveFailure& e) noexcept;
// Found by ADL when value() is called on a failed Result: throws std::system_error
// carrying the code and the message.
[[noreturn]] void outcome_throw_as_system_error_with_payload(const ArchiveFailure& e);

template <class T>
using Result = boost::outcome_v2::std_result<T, ArchiveFailure>;

// "<context>: <the code's message>".
ArchiveFailure archive_error(ArchiveError code, std::string_view context);

// The words of kNotAnArchive for an empty database opened read-only (a server's schema with no
// tables): what a caller that can create the archive adds its hint to.
inline constexpr std::string_view kNoArchiveYet = "holds no archive yet";
// The words of kReadOnly for an archive of an older schema opened read-only: a read cannot
// migrate it, and a caller that can open it for writing adds that hint.
inline constexpr std::string_view kNeedsMigration = "needs a migration";

// Runs f() (returning a Result) and prefixes an error's message with "<operation>: ".
template <class F>
auto with_context(std::string_view operation, F&& f) -> decltype(f()) {
  auto result = f();
  if (result.has_error()) {
    result.error().message.insert(0, std::string(operation) + ": ");
  }
  return result;
}

}  // namespace rs4sim::storage

template <>
struct std::is_error_code_enum<rs4sim::storage::ArchiveError> : std::true_type {};
