// The gRPC API on loopback (docs/rpc.md): unary latency (p50/p99 of Observation.GetState and
// SimTime.Now, targets p50 ≤ 150 µs) and the event stream's throughput with every telegram
// (target ≥ 50k events/s), in front of a simulated RS4 segment whose loop has its own thread.
#include "rpc/executor.h"
#include "rpc/rs4_services.h"
#include "rpc/segment_target.h"
#include "rpc/server.h"
#include "rs4sim/v1/rs4.grpc.pb.h"

#include <benchmark/benchmark.h>
#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>
#include <thread>
#include <vector>

namespace rs4sim::rpc {
namespace {

using Clock = std::chrono::steady_clock;

struct Rig {
  Rig() {
    segment.power_on();
    loop = std::thread([this] { io.run(); });
    server = std::make_unique<RpcServer>(ServerOptions{},
                                         std::vector<grpc::Service*>{&observation, &time});
    channel = grpc::CreateChannel(server->address(), grpc::InsecureChannelCredentials());
    observation_stub = v1::Observation::NewStub(channel);
    time_stub = v1::SimTime::NewStub(channel);
  }
  ~Rig() {
    server->shutdown();
    work.reset();
    loop.join();
  }
  Rig(const Rig&) = delete;
  Rig& operator=(const Rig&) = delete;
  void advance(std::uint64_t ms) {
    grpc::ClientContext ctx;
    v1::AdvanceRequest req;
    req.set_duration_ms(ms);
    v1::TimeResponse t;
    (void)time_stub->Advance(&ctx, req, &t);
  }

  rs4::device::Rs4Segment segment{rs4::device::Rs4SegmentConfig{}};
  boost::asio::io_context io;
  std::optional<boost::asio::executor_work_guard<boost::asio::io_context::executor_type>> work{
      io.get_executor()};
  std::thread loop;
  SegmentTarget target{segment};
  AsioExecutor executor{io};
  ObservationService observation{{target, executor}};
  SimTimeService time{{target, executor}};
  std::unique_ptr<RpcServer> server;
  std::shared_ptr<grpc::Channel> channel;
  std::unique_ptr<v1::Observation::Stub> observation_stub;
  std::unique_ptr<v1::SimTime::Stub> time_stub;
};

void report_percentiles(benchmark::State& state, std::vector<double>& us) {
  if (us.empty()) return;
  std::sort(us.begin(), us.end());
  state.counters["p50_us"] = us[us.size() / 2];
  state.counters["p99_us"] = us[std::min(us.size() - 1, us.size() * 99 / 100)];
}

template <typename Call>
void unary(benchmark::State& state, Call call) {
  Rig rig;
  rig.advance(1000);
  std::vector<double> us;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    call(rig);
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }
  report_percentiles(state, us);
}

void BM_UnaryGetState(benchmark::State& state) {
  unary(state, [](Rig& rig) {
    grpc::ClientContext ctx;
    v1::StationRequest req;
    req.set_address(4);
    v1::DeviceState out;
    benchmark::DoNotOptimize(rig.observation_stub->GetState(&ctx, req, &out).ok());
  });
}
BENCHMARK(BM_UnaryGetState)->UseRealTime();

void BM_UnaryNow(benchmark::State& state) {
  unary(state, [](Rig& rig) {
    grpc::ClientContext ctx;
    v1::Empty req;
    v1::TimeResponse out;
    benchmark::DoNotOptimize(rig.time_stub->Now(&ctx, req, &out).ok());
  });
}
BENCHMARK(BM_UnaryNow)->UseRealTime();

// Every telegram of the segment as an event: each iteration advances 10 s of simulated time
// (≈1000 cycles); a reader thread drains the stream; events/s = all events read / wall time.
void BM_EventStreamTelegrams(benchmark::State& state) {
  Rig rig;
  grpc::ClientContext ctx;
  v1::StreamEventsRequest req;
  req.set_telegrams(true);
  req.set_queue_capacity(1U << 20U);
  auto reader = rig.observation_stub->StreamEvents(&ctx, req);
  std::atomic<std::uint64_t> events{0};
  std::atomic<std::int64_t> last_ns{0};
  std::thread drain([&] {
    v1::Event e;
    while (reader->Read(&e)) {
      events.fetch_add(1, std::memory_order_relaxed);
      last_ns.store(e.now_ns(), std::memory_order_relaxed);
    }
  });
  // The call returns before the server has subscribed: wait for the snapshot's first event.
  while (events.load() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const auto t0 = Clock::now();
  for (auto _ : state) rig.advance(10'000);
  std::int64_t end_ns = 0;
  rig.executor.run([&] {
    end_ns =
        std::chrono::duration_cast<std::chrono::nanoseconds>(rig.segment.now().time_since_epoch())
            .count();
  });
  while (last_ns.load() + 20'000'000 < end_ns && Clock::now() - t0 < std::chrono::seconds(60)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  ctx.TryCancel();
  drain.join();
  (void)reader->Finish();
  state.counters["events"] = static_cast<double>(events.load());
  state.counters["events_per_s"] = static_cast<double>(events.load()) / seconds;
}
BENCHMARK(BM_EventStreamTelegrams)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rs4sim::rpc
