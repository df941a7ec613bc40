#pragma once
// The archive both storage benchmarks measure: `sets` distinct 8507-byte sets, 100 versions
// per station, imported 50 stations at a time (one transaction each).
#include "storage/crc32.h"
#include "storage/parameter_archive.h"
#include "tests/storage/archive_test_support.h"

#include <cstdint>
#include <string>
#include <utility>

namespace rs4sim::storage::bench {

inline void populate(ParameterArchive& archive, std::int64_t sets) {
  constexpr std::uint32_t kVersionsPerStation = 100;
  constexpr std::uint32_t kStationsPerBatch = 50;
  std::uint64_t seed = 0;
  std::uint32_t station = 0;
  for (std::int64_t done = 0; done < sets;) {
    Snapshot snap;
    for (std::uint32_t s = 0; s < kStationsPerBatch && done < sets; ++s, ++station) {
      SnapshotStation st;
      st.key = {"bus" + std::to_string(station / 100), static_cast<std::uint8_t>(station % 100)};
      for (std::uint32_t n = 1; n <= kVersionsPerStation && done < sets; ++n, ++done) {
        const auto blob = testing::make_blob(++seed);
        const auto id = static_cast<SetId>(snap.sets.size() + 1);
        snap.sets.push_back({id, crc32(blob), blob, "{}"});
        SnapshotVersion v;
        v.number = n;
        v.set_id = id;
        v.serial_number = "SN";
        st.versions.push_back(std::move(v));
        st.current_version = n;
      }
      snap.stations.push_back(std::move(st));
    }
    archive.import_snapshot(snap).value();
  }
}

}  // namespace rs4sim::storage::bench
