// A complete parameter set up- and downloaded by the proxy (ProxySync) over the in-memory bus
// to the real device (master + F-host + Rs4Device, Rs4Segment), with the wire modelled at the
// baud rate. Reports wall time per sync and the simulated time against the raw set's wire
// time: 8507 bytes × 11 bits (one UART character per byte, [IEC 61158-4-3 frame formats]).
//   build/bench/proxy/bench_proxy --benchmark_repetitions=3
#include "proxy/proxy_sync.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_segment.h"
#include "rs4/scanner/parameter_codec.h"
#include "storage/sqlite_archive.h"

#include <benchmark/benchmark.h>

#include <memory>

namespace rs4sim {
namespace {

using namespace std::chrono_literals;
using proxy::RecordResult;

struct Rig {
  explicit Rig(dp::BaudRate baud) : seg(config(baud)) {}
  static rs4::device::Rs4SegmentConfig config(dp::BaudRate baud) {
    rs4::device::Rs4SegmentConfig c;
    c.device.switches = rs4::device::switches_for(4);
    c.device.boot_time = 1000ms;
    c.master.address = 4;
    c.baud = baud;
    c.bus.wire_model = baud;
    c.cycle_target = 200us;  // acyclic records as fast as the bus allows
    c.output_byte = rs4::adapter::kOutputProxyEnable | 0x01;
    return c;
  }
  RecordResult exchange(const proxy::RecordRequest& request) {
    const auto* w = std::get_if<proxy::RecordWrite>(&request);
    const auto r = w != nullptr ? seg.write_record(w->data)
                                : seg.read_record(std::get<proxy::RecordRead>(request).length);
    if (!r || r->error) return RecordResult::no_response();
    return RecordResult::success({r->data.begin(), r->data.end()});
  }
  // Boots the device with `device_set` and runs one sync; the simulated duration of the sync.
  std::optional<dp::Duration> sync_once(const rs4::scanner::ParameterSet& device_set,
                                        proxy::ProxySync& sync) {
    (void)seg.device().scanner().set_parameters(device_set, seg.now());
    seg.power_on();
    if (!seg.run_until([&] { return (seg.input_byte() & rs4::adapter::kInputProxyRequest) != 0; },
                       10s)) {
      return std::nullopt;
    }
    sync.set_proxy_enable(true);
    sync.set_input_byte(seg.input_byte());
    const auto t0 = seg.now();
    sync.start(t0);
    while (sync.active() && seg.now() - t0 < 60s) {
      if (auto req = sync.take_request(seg.now())) {
        sync.on_record_result(exchange(*req), seg.now());
      } else {
        seg.run_for(100us);
        sync.tick(seg.now());
      }
      sync.set_input_byte(seg.input_byte());
    }
    if (sync.active() || !(sync.outputs() == proxy::FbOutputs{})) return std::nullopt;
    return seg.now() - t0;
  }
  rs4::device::Rs4Segment seg;
};

rs4::scanner::ParameterSet changed_set() {
  auto set = rs4::scanner::factory_default();
  set.response_steps = 4;
  return set;
}

void run(benchmark::State& state, dp::BaudRate baud, bool download) {
  double simulated_s = 0;
  std::int64_t n = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto archive = storage::SqliteArchive::open(":memory:").value();
    proxy::ProxySyncConfig c;
    c.station = {"bench", 4};
    c.background_verify = false;
    proxy::ProxySync sync(c, *archive);
    auto rig = std::make_unique<Rig>(baud);
    if (download) {  // a new device (factory settings, other serial): the stored set goes down
      const auto set = changed_set();
      const auto blob = rs4::scanner::encode_for_transfer(set);
      storage::StoreRequest r;
      r.station = c.station;
      r.serial_number = "1";
      r.blob = blob;
      r.crc32 = rs4::scanner::transfer_checksum(set);
      (void)archive->store(r);
    }
    state.ResumeTiming();
    const auto d = rig->sync_once(download ? rs4::scanner::factory_default() : changed_set(), sync);
    if (!d) {
      state.SkipWithError("the sync did not complete");
      return;
    }
    simulated_s += std::chrono::duration<double>(*d).count();
    ++n;
  }
  const double wire_s =
      std::chrono::duration<double>(dp::bit_time(baud, rs4::scanner::kParameterSetSize * 11U))
          .count();
  state.counters["simulated_ms"] = 1000 * simulated_s / static_cast<double>(n);
  state.counters["raw_wire_ms"] = 1000 * wire_s;
  state.counters["ratio"] = simulated_s / static_cast<double>(n) / wire_s;
}

void BM_UploadSync_1M5(benchmark::State& s) { run(s, dp::BaudRate::k1M5, false); }
void BM_DownloadSync_1M5(benchmark::State& s) { run(s, dp::BaudRate::k1M5, true); }
void BM_UploadSync_12M(benchmark::State& s) { run(s, dp::BaudRate::k12M, false); }
void BM_DownloadSync_12M(benchmark::State& s) { run(s, dp::BaudRate::k12M, true); }
BENCHMARK(BM_UploadSync_1M5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DownloadSync_1M5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_UploadSync_12M)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DownloadSync_12M)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rs4sim
