#include "storage/types.h"

namespace rs4sim::storage {

const char* to_string(VersionSource s) noexcept {
  switch (s) {
    case VersionSource::kUpload: return "upload";
    case VersionSource::kDownload: return "download";
    case VersionSource::kImport: return "import";
    case VersionSource::kRestore: return "restore";
  }
  return "unknown";
}

}  // namespace rs4sim::storage
