#include "storage/errors.h"

namespace rs4sim::storage {
namespace {

class ArchiveCategory final : public std::error_category {
 public:
  const char* name() const noexcept override { return "rs4sim.archive"; }
  std::string message(int v) const override {
    switch (static_cast<ArchiveErrc>(v)) {
      case ArchiveErrc::kUnknownStation: return "unknown station";
      case ArchiveErrc::kUnknownVersion: return "unknown version";
      case ArchiveErrc::kNotFound: return "not found";
      case ArchiveErrc::kNotAnArchive: return "not an rs4sim archive";
      case ArchiveErrc::kNewerSchema: return "archive written by a newer rs4sim";
      case ArchiveErrc::kCorruptImport: return "corrupt import file";
      case ArchiveErrc::kCrcMismatch: return "CRC-32 mismatch";
      case ArchiveErrc::kInvalidArgument: return "invalid argument";
      case ArchiveErrc::kBusy: return "archive locked by another writer";
      case ArchiveErrc::kReadOnly: return "archive is read-only";
      case ArchiveErrc::kDiskFull: return "disk full";
      case ArchiveErrc::kCorruptArchive: return "archive file corrupt";
      case ArchiveErrc::kIo: return "archive I/O error";
    }
    return "unknown archive error";
  }
};

}  // namespace

const std::error_category& archive_category() noexcept {
  static const ArchiveCategory category;
  return category;
}

std::error_code make_error_code(ArchiveErrc e) noexcept {
  return {static_cast<int>(e), archive_category()};
}

ArchiveError archive_error(ArchiveErrc code, std::string_view context) {
  return ArchiveError{code, std::string(context) + ": " + make_error_code(code).message()};
}

std::error_code make_error_code(const ArchiveError& e) noexcept { return make_error_code(e.code); }

void outcome_throw_as_system_error_with_payload(const ArchiveError& e) {
  throw std::system_error(make_error_code(e.code), e.message);
}

}  // namespace rs4sim::storage
