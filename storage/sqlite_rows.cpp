#include "storage/sqlite_rows.h"

namespace rs4sim::storage {

VersionInfo read_version(const sqlite::Statement& s) {
  VersionInfo v;
  v.id = s.int64(0);
  v.station = StationKey{s.text(1), static_cast<std::uint8_t>(s.int64(2))};
  v.number = static_cast<std::uint32_t>(s.int64(3));
  v.set_id = s.int64(4);
  v.crc32 = static_cast<std::uint32_t>(s.int64(5));
  v.size = static_cast<std::uint32_t>(s.int64(6));
  v.source = static_cast<VersionSource>(s.int64(7));
  v.at = from_ms(s.int64(8));
  v.note = s.text(9);
  if (!s.is_null(10)) v.restored_from = s.int64(10);
  v.pending_download = s.int64(11) != 0;
  v.serial_number = s.text(12);
  v.user = s.text(13);
  v.host = s.text(14);
  if (!s.is_null(15)) v.simulated = std::chrono::milliseconds{s.int64(15)};
  return v;
}

}  // namespace rs4sim::storage
