#include "storage/errors.h"

namespace rs4sim::storage {

std::string_view to_string(ArchiveError e) noexcept {
  switch (e) {
    case ArchiveError::kUnknownStation: return "unknown station";
    case ArchiveError::kUnknownVersion: return "unknown version";
    case ArchiveError::kNotFound: return "not found";
    case ArchiveError::kNotAnArchive: return "not an rs4sim archive";
    case ArchiveError::kNewerSchema: return "archive written by a newer rs4sim";
    case ArchiveError::kCorruptImport: return "corrupt import file";
    case ArchiveError::kCrcMismatch: return "CRC-32 mismatch";
    case ArchiveError::kInvalidArgument: return "invalid argument";
    case ArchiveError::kBusy: return "archive locked by another writer";
    case ArchiveError::kReadOnly: return "archive is read-only";
    case ArchiveError::kDiskFull: return "disk full";
    case ArchiveError::kCorruptArchive: return "archive file corrupt";
    case ArchiveError::kIo: return "archive I/O error";
  }
  return "unknown archive error";
}

ArchiveFailure archive_error(ArchiveError code, std::string_view context) {
  return ArchiveFailure{code, std::string(context) + ": " + make_error_code(code).message()};
}

std::error_code make_error_code(const ArchiveFailure& e) noexcept {
  return make_error_code(e.code);
}

void outcome_throw_as_system_error_with_payload(const ArchiveFailure& e) {
  throw std::system_error(make_error_code(e.code), e.message);
}

}  // namespace rs4sim::storage
