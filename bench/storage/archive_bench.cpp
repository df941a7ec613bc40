// SqliteArchive on a real file: store throughput with 8507-byte sets (distinct contents,
// and with deduplication hits), current-set lookup in an archive of N stored sets, and
// the history of a station with 1000 versions.
#include "bench/storage/populate.h"
#include "storage/sqlite_archive.h"
#include "tests/storage/archive_test_support.h"

#include <benchmark/benchmark.h>

#include <cstring>

namespace rs4sim::storage {
namespace {

using testing::make_blob;
using testing::request;

std::unique_ptr<SqliteArchive> open_archive(const std::filesystem::path& file, bool full) {
  SqliteOptions options;
  options.synchronous_full = full;
  return SqliteArchive::open(file, options).value();
}

// arg 0: synchronous FULL (1) or NORMAL (0).
void BM_StoreDistinct(benchmark::State& state) {
  testing::TempDir dir;
  auto archive = open_archive(dir.file("a.sqlite3"), state.range(0) != 0);
  auto blob = make_blob(1);
  std::uint64_t counter = 0;
  for (auto _ : state) {
    ++counter;
    std::memcpy(blob.data(), &counter, sizeof counter);  // new content every time
    auto r = request({"bus1", static_cast<std::uint8_t>(counter % 100)}, blob);
    benchmark::DoNotOptimize(archive->store(r).value());
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(blob.size()));
}
BENCHMARK(BM_StoreDistinct)->ArgName("sync_full")->Arg(1)->Arg(0)->UseRealTime();

void BM_StoreDuplicate(benchmark::State& state) {
  testing::TempDir dir;
  auto archive = open_archive(dir.file("a.sqlite3"), state.range(0) != 0);
  const auto blob = make_blob(1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(archive->store(request({"bus1", 4}, blob)).value());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_StoreDuplicate)->ArgName("sync_full")->Arg(1)->Arg(0)->UseRealTime();

using bench::populate;

void BM_CurrentLookup(benchmark::State& state) {
  testing::TempDir dir;
  auto archive = open_archive(dir.file("a.sqlite3"), false);
  populate(*archive, state.range(0));
  const auto stations = archive->stations().value();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& key = stations[(i++ * 7919) % stations.size()].key;
    benchmark::DoNotOptimize(archive->current(key).value());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CurrentLookup)
    ->ArgName("stored_sets")
    ->Arg(1000)
    ->Arg(100000)
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(20000);

void BM_History1000(benchmark::State& state) {
  testing::TempDir dir;
  auto archive = open_archive(dir.file("a.sqlite3"), false);
  const auto blob = make_blob(1);
  for (int i = 0; i < 1000; ++i) archive->store(request({"bus1", 4}, blob, i)).value();
  for (auto _ : state) {
    auto history = archive->history({"bus1", 4}).value();
    if (history.size() != 1000) state.SkipWithError("history is not 1000 versions");
    benchmark::DoNotOptimize(history);
  }
  state.SetItemsProcessed(state.iterations() * 1000);
}
BENCHMARK(BM_History1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace rs4sim::storage
