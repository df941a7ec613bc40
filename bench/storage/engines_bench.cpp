// SQLite and PostgreSQL side by side, in one run (so the ratio holds on a loaded machine):
// stores per second for one writer and for 8 concurrent writers (each its own connection and
// its own bus, as masters of 8 lines), and current() latency p50/p99 with N stored sets.
//
// The PostgreSQL half needs a server: RS4SIM_BENCH_POSTGRES_URI=postgresql://… (each benchmark
// works in a schema of its own, dropped afterwards); without it those benchmarks are skipped.
//   tests/storage/postgres_server.sh start pg-dir
//   RS4SIM_BENCH_POSTGRES_URI=$(cat pg-dir/uri) build/bench/storage/bench_storage_engines
#include "bench/storage/populate.h"
#include "storage/crc32.h"
#include "storage/open_archive.h"
#include "tests/storage/archive_test_support.h"

#include <benchmark/benchmark.h>
#include <libpq-fe.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace rs4sim::storage {
namespace {

using testing::make_blob;
using testing::request;

enum Engine : std::int64_t { kSqlite = 0, kPostgres = 1 };

const char* server() {
  const char* uri = std::getenv("RS4SIM_BENCH_POSTGRES_URI");
  return uri != nullptr && *uri != '\0' ? uri : nullptr;
}

void quiet(void* /*arg*/, const char* /*message*/) {}

void raw(const std::string& sql) {
  PGconn* c = PQconnectdb(server());
  PQsetNoticeProcessor(c, &quiet, nullptr);
  PQclear(PQexec(c, sql.c_str()));
  PQfinish(c);
}

// A fresh, empty archive location of the engine, removed when the object goes.
class Place {
 public:
  Place(Engine engine, const std::string& name) : engine_(engine) {
    if (engine_ == kSqlite) {
      location_ = dir_.file(name + ".sqlite3").string();
    } else {
      schema_ = "rs4sim_bench_" + name;
      raw("DROP SCHEMA IF EXISTS " + schema_ + " CASCADE; CREATE SCHEMA " + schema_);
      const std::string uri = server();
      location_ = uri + (uri.find('?') == std::string::npos ? "?" : "&") +
                  "options=-csearch_path%3D" + schema_;
    }
  }
  Place(const Place&) = delete;
  Place& operator=(const Place&) = delete;
  ~Place() {
    if (engine_ == kPostgres) raw("DROP SCHEMA IF EXISTS " + schema_ + " CASCADE");
  }
  std::unique_ptr<ParameterArchive> open() const { return open_archive(location_).value(); }

 private:
  Engine engine_;
  testing::TempDir dir_;
  std::string schema_;
  std::string location_;
};

bool skipped(benchmark::State& state) {
  if (state.range(0) == kPostgres && server() == nullptr) {
    state.SkipWithError("RS4SIM_BENCH_POSTGRES_URI is not set");
    return true;
  }
  return false;
}

// Distinct 8507-byte sets; each thread (writer) stores into its own bus.
void BM_Store(benchmark::State& state) {
  if (skipped(state)) return;
  // One place for all writers of a run: the first to arrive makes it (and its schema); each
  // writer holds it until it is done, the last one removes it.
  static std::mutex setup;
  static std::shared_ptr<Place> shared;
  std::shared_ptr<Place> place;
  std::unique_ptr<ParameterArchive> archive;
  {
    std::lock_guard lock(setup);
    if (!shared) {
      shared = std::make_shared<Place>(static_cast<Engine>(state.range(0)), "store");
      shared->open();
    }
    place = shared;
    archive = place->open();
  }
  auto blob = make_blob(static_cast<std::uint64_t>(state.thread_index()) + 1);
  std::uint64_t counter = static_cast<std::uint64_t>(state.thread_index()) << 40U;
  const std::string bus = "line" + std::to_string(state.thread_index());
  for (auto _ : state) {
    ++counter;
    std::memcpy(blob.data(), &counter, sizeof counter);
    auto r = request({bus, static_cast<std::uint8_t>(counter % 100)}, blob);
    benchmark::DoNotOptimize(archive->store(r).value());
  }
  state.SetItemsProcessed(state.iterations());
  archive.reset();
  // Every writer has taken the place before the loop starts (the loop begins on a barrier of
  // all threads), so the next run finds none.
  std::lock_guard lock(setup);
  shared.reset();
}
BENCHMARK(BM_Store)
    ->ArgName("postgres")
    ->Arg(kSqlite)
    ->Arg(kPostgres)
    ->Threads(1)
    ->Threads(8)
    ->UseRealTime();

using bench::populate;

// current() of stations in a scattered order; p50 and p99 of the single calls as counters.
void BM_Current(benchmark::State& state) {
  if (skipped(state)) return;
  Place place(static_cast<Engine>(state.range(0)), "current");
  auto archive = place.open();
  populate(*archive, state.range(1));
  const auto stations = archive->stations().value();
  std::vector<double> micros;
  micros.reserve(static_cast<std::size_t>(state.max_iterations));
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& key = stations[(i++ * 7919) % stations.size()].key;
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(archive->current(key).value());
    micros.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
            .count());
  }
  std::sort(micros.begin(), micros.end());
  const auto at = [&](double q) {
    return micros[static_cast<std::size_t>(q * static_cast<double>(micros.size() - 1))];
  };
  state.counters["p50_us"] = at(0.50);
  state.counters["p99_us"] = at(0.99);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Current)
    ->ArgNames({"postgres", "stored_sets"})
    ->Args({kSqlite, 1000})
    ->Args({kPostgres, 1000})
    ->Args({kSqlite, 100000})
    ->Args({kPostgres, 100000})
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(20000)
    ->UseRealTime();

}  // namespace
}  // namespace rs4sim::storage
