// The Proxy service on a real gRPC server on loopback (docs/rpc.md "Proxy"): the FB outputs
// of [RS4 manual §6.4] field by field, the progress stream's snapshot, changes and end, its
// bounded mailbox, and the bad-input statuses. The statuses come from a scheduler stand-in on
// the loop thread, so every value the client sees is one the test set; the real scheduler
// behind it is covered end to end by python_master_proxy_test.py (two processes, UDP).
#include "http_front.h"
#include "proxy/proxy_scheduler.h"
#include "rpc/executor.h"
#include "rpc/proxy_service.h"
#include "rpc/server.h"
#include "rs4_fixture.h"
#include "rs4sim/v1/proxy_service.grpc.pb.h"
#include "test_loop.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <gtest/gtest.h>

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

#include <thread>

namespace rs4sim::rpc {
namespace {

proxy::StationStatus idle(std::uint8_t address) {
  proxy::StationStatus s;
  s.address = address;
  return s;
}

proxy::StationStatus uploading(std::uint8_t address, std::size_t done) {
  proxy::StationStatus s;
  s.address = address;
  s.running = true;
  s.progress.step = proxy::Step::kUpload1;
  s.progress.position = 0x21;
  s.progress.bytes_done = done;
  s.progress.bytes_total = 8507;
  s.progress.direction = rs4::protocol::SyncDirection::kUpload;
  s.outputs.fb_busy = true;
  return s;
}

class RpcProxyTest : public ::testing::Test, protected ServedLoop {
 protected:
  void SetUp() override {
    statuses_ = {idle(4), idle(5)};
    ProxySource source;
    source.bus = "line-3";
    source.max_parallel = 1;
    source.status = [this] { return statuses_; };
    source.queue = [this] { return queue_; };
    source.now_ns = [this] { return now_ns_; };
    service_ = std::make_unique<ProxyService>(std::move(source), feed_, executor_);
    stub_ = serve<v1::Proxy>(*service_);
  }
  void TearDown() override { stop_serving(); }
  // On the loop thread, as the master's cycle does it: the new status, then publish.
  void change(const proxy::StationStatus& s, std::int64_t now_ns) {
    executor_.run([&] {
      now_ns_ = now_ns;
      for (auto& mine : statuses_) {
        if (mine.address == s.address) mine = s;
      }
      feed_.publish(s, "line-3", now_ns);
    });
  }
  grpc::Status get(std::vector<std::uint32_t> addresses, v1::ProxyStatusResponse& out) {
    grpc::ClientContext ctx;
    v1::ProxyStatusRequest req;
    for (const auto a : addresses) req.add_addresses(a);
    return stub_->GetStatus(&ctx, req, &out);
  }
  std::unique_ptr<grpc::ClientReader<v1::ProxyStationStatus>> watch(
      grpc::ClientContext& ctx, std::vector<std::uint32_t> addresses, bool until_done) {
    ctx.set_deadline(std::chrono::system_clock::now() + 20s);
    v1::WatchSyncRequest req;
    for (const auto a : addresses) req.add_addresses(a);
    req.set_until_sync_done(until_done);
    return stub_->WatchSync(&ctx, req);
  }

  std::vector<proxy::StationStatus> statuses_;
  std::vector<std::uint8_t> queue_;
  std::int64_t now_ns_ = 1'000'000;
  ProxyFeed feed_;
  std::unique_ptr<ProxyService> service_;
  std::unique_ptr<v1::Proxy::Stub> stub_;
};

TEST_F(RpcProxyTest, GetStatusShowsTheFbOutputsAndTheQueue) {
  auto busy = uploading(4, 2048);
  busy.outputs.error_number_fb = 0x2101;  // position 0x21, KK 01: a WRITE refused
  busy.outputs.error_code_sfc = 0xDF80;
  busy.outputs.error_number_rs4 = 0x53;
  auto waiting = idle(5);
  waiting.queue_position = 0;
  change(busy, 7'000'000);
  change(waiting, 7'000'000);
  executor_.run([&] { queue_ = {5}; });

  v1::ProxyStatusResponse out;
  ASSERT_TRUE(get({}, out).ok());
  EXPECT_EQ(out.bus(), "line-3");
  EXPECT_EQ(out.max_parallel(), 1U);
  EXPECT_EQ(out.running(), 1U);
  ASSERT_EQ(out.queue_size(), 1);
  EXPECT_EQ(out.queue(0), 5U);
  ASSERT_EQ(out.stations_size(), 2);
  const auto& s4 = out.stations(0);
  EXPECT_EQ(s4.bus(), "line-3");
  EXPECT_EQ(s4.address(), 4U);
  EXPECT_TRUE(s4.running());
  EXPECT_EQ(s4.queue_position(), -1);
  EXPECT_EQ(s4.step(), "upload chunk");
  EXPECT_EQ(s4.position(), 0x21U);
  EXPECT_EQ(s4.bytes_done(), 2048U);
  EXPECT_EQ(s4.bytes_total(), 8507U);
  EXPECT_EQ(s4.direction(), "upload");
  EXPECT_TRUE(s4.outputs().fb_busy());
  EXPECT_FALSE(s4.outputs().config_set_to_default());
  EXPECT_EQ(s4.outputs().error_number_fb(), 0x2101U);
  EXPECT_EQ(s4.outputs().error_code_sfc(), 0xDF80U);
  EXPECT_EQ(s4.outputs().error_number_rs4(), 0x53U);
  EXPECT_EQ(s4.now_ns(), 7'000'000);
  const auto& s5 = out.stations(1);
  EXPECT_EQ(s5.address(), 5U);
  EXPECT_FALSE(s5.running());
  EXPECT_EQ(s5.queue_position(), 0);
  EXPECT_EQ(s5.step(), "idle");
  EXPECT_EQ(s5.direction(), "none");

  v1::ProxyStatusResponse only5;
  ASSERT_TRUE(get({5}, only5).ok());
  ASSERT_EQ(only5.stations_size(), 1);
  EXPECT_EQ(only5.stations(0).address(), 5U);
  EXPECT_EQ(only5.running(), 1U);  // the scheduler's figures stay whole
}

TEST_F(RpcProxyTest, BadAddressesGetASpecificStatus) {
  v1::ProxyStatusResponse out;
  auto s = get({127}, out);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "addresses[0]");
  s = get({4, 9}, out);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_NE(s.error_message().find("station 9"), std::string::npos) << s.error_message();
  EXPECT_NE(s.error_message().find("line-3"), std::string::npos) << s.error_message();

  grpc::ClientContext ctx;
  auto reader = watch(ctx, {5, 300}, true);
  v1::ProxyStationStatus e;
  EXPECT_FALSE(reader->Read(&e));
  s = reader->Finish();
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "addresses[1]");
  grpc::ClientContext ctx2;
  auto reader2 = watch(ctx2, {6}, true);
  EXPECT_FALSE(reader2->Read(&e));
  EXPECT_EQ(reader2->Finish().error_code(), grpc::StatusCode::NOT_FOUND);
}

TEST_F(RpcProxyTest, WatchSyncSnapshotThenProgressThenEndsAfterTheSync) {
  grpc::ClientContext ctx;
  auto reader = watch(ctx, {4}, true);
  v1::ProxyStationStatus e;
  ASSERT_TRUE(reader->Read(&e));  // the snapshot: the server has subscribed
  EXPECT_EQ(e.address(), 4U);
  EXPECT_EQ(e.step(), "idle");
  EXPECT_FALSE(e.running());

  change(idle(5), 2'000'000);  // another RS4: not watched
  for (std::size_t done = 0; done <= 8192; done += 1024) {
    change(uploading(4, done), 2'000'000 + static_cast<std::int64_t>(done));
  }
  auto end = idle(4);
  end.outputs.config_set_to_default = false;
  change(end, 9'000'000);

  std::vector<v1::ProxyStationStatus> seen;
  while (reader->Read(&e)) seen.push_back(e);
  EXPECT_TRUE(reader->Finish().ok());
  ASSERT_GE(seen.size(), 2U);  // at least the latest progress and the end
  for (const auto& s : seen) EXPECT_EQ(s.address(), 4U);
  std::uint64_t last_done = 0;
  for (std::size_t i = 0; i + 1 < seen.size(); ++i) {
    EXPECT_TRUE(seen[i].running());
    EXPECT_GE(seen[i].bytes_done(), last_done);  // coalesced, never out of order
    last_done = seen[i].bytes_done();
  }
  EXPECT_EQ(last_done, 8192U);  // the newest progress is never the one dropped
  EXPECT_FALSE(seen.back().running());
  EXPECT_EQ(seen.back().now_ns(), 9'000'000);
}

TEST_F(RpcProxyTest, WithoutUntilDoneTheStreamStaysUntilTheRunEnds) {
  grpc::ClientContext ctx;
  auto reader = watch(ctx, {}, false);
  v1::ProxyStationStatus e;
  ASSERT_TRUE(reader->Read(&e));
  ASSERT_TRUE(reader->Read(&e));  // both RS4s in the snapshot
  change(uploading(5, 0), 3'000'000);
  change(idle(5), 4'000'000);  // a sync ended: the stream goes on
  ASSERT_TRUE(reader->Read(&e));
  EXPECT_TRUE(e.running());
  ASSERT_TRUE(reader->Read(&e));
  EXPECT_FALSE(e.running());
  executor_.run([&] { feed_.close(); });  // the server stops: the stream ends
  EXPECT_FALSE(reader->Read(&e));
  EXPECT_TRUE(reader->Finish().ok());
}

// The mailbox itself: a client that does not read holds one status per RS4 plus the
// transitions between running and not, bounded whatever the loop publishes.
TEST(ProxyWatch, KeepsTheLatestProgressAndEveryTransition) {
  ProxyWatch watch({});
  v1::ProxyStationStatus s;
  s.set_address(4);
  s.set_queue_position(-1);  // not waiting (0 would be "next in the queue")
  for (std::uint64_t done = 0; done < 1000; ++done) {
    s.set_running(true);
    s.set_bytes_done(done);
    watch.put(s);
  }
  s.set_running(false);
  s.set_bytes_done(0);
  watch.put(s);  // the end of a sync is kept
  s.set_running(true);
  s.set_bytes_done(5);
  watch.put(s);  // and the next sync's start queues behind it
  const auto got = watch.take(std::chrono::milliseconds(0));
  ASSERT_EQ(got.size(), 3U);
  EXPECT_EQ(got[0].bytes_done(), 999U);
  EXPECT_FALSE(got[1].running());
  EXPECT_EQ(got[2].bytes_done(), 5U);
  EXPECT_TRUE(watch.take(std::chrono::milliseconds(0)).empty());

  for (int i = 0; i < 100; ++i) {  // a sync per put: bounded all the same
    s.set_running(i % 2 == 0);
    watch.put(s);
  }
  EXPECT_LE(watch.take(std::chrono::milliseconds(0)).size(), 16U);
}

TEST(ProxyWatch, AStatusIsMappedFieldByField) {
  auto s = uploading(7, 1024);
  s.queue_position = 2;
  s.progress.step = proxy::Step::kDownloadChunk;
  s.progress.direction = rs4::protocol::SyncDirection::kDownload;
  s.outputs.config_set_to_default = true;
  v1::ProxyStationStatus out;
  fill_proxy_status(s, "b", 42, out);
  EXPECT_EQ(out.bus(), "b");
  EXPECT_EQ(out.address(), 7U);
  EXPECT_EQ(out.queue_position(), 2);
  EXPECT_EQ(out.step(), "download chunk");
  EXPECT_EQ(out.direction(), "download");
  EXPECT_TRUE(out.outputs().config_set_to_default());
  EXPECT_EQ(out.now_ns(), 42);
}

// The same service as JSON over HTTP (docs/http.md).
TEST_F(RpcProxyTest, JsonOverHttpIsTheSameService) {
  HttpFront h(io_, *server_);
  const auto got = h.call("rs4sim.v1.Proxy/GetStatus", R"({"addresses": [5]})");
  ASSERT_EQ(got.status, 200u) << got.body;
  v1::ProxyStatusResponse over_grpc;
  ASSERT_TRUE(get({5}, over_grpc).ok());
  EXPECT_EQ(from_json<v1::ProxyStatusResponse>(got.body).SerializeAsString(),
            over_grpc.SerializeAsString());
  error_of(h.call("rs4sim.v1.Proxy/GetStatus", R"({"addresses": [300]})"), 400, 3);
  error_of(h.call("rs4sim.v1.Proxy/WatchSync"), 501, 12);  // a stream: not over HTTP
}

}  // namespace
}  // namespace rs4sim::rpc
