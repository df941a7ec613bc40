// The RS-485 devices on the simulated clock through the API, as `rs4sim run --device X
// --link memory --grpc` serves them (rpc/line_target.h): the device's tap on a MemoryLine on
// the manual clock, a real gRPC server on loopback, SimTime, and each service's Exchange and
// Receive. The known answers are the manuals' printed frames, as fixed bytes: the GridScan's
// [GridScan manual §10.3] communication test from power-up, the Polaris's P1..P8
// [Polaris manual §7.4, §8.2.3], the METRON's error answers [METRON manual "No node"]. Wire
// times are computed by hand from the line formats: 115200 8N1 (GridScan, 10 bits:
// 86805.6 ns a character), 19200 8N1 (Polaris, 520833.3 ns), 19200 8E1 (METRON, 11 bits:
// 572916.7 ns).
#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"
#include "rpc/executor.h"
#include "rpc/gridscan_service.h"
#include "rpc/line_target.h"
#include "rpc/metron_service.h"
#include "rpc/polaris_service.h"
#include "rpc/rs4_services.h"
#include "rpc/server.h"
#include "rpc/service_support.h"
#include "rpc_calls.h"
#include "rs4sim/v1/devices.grpc.pb.h"
#include "test_loop.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <gtest/gtest.h>

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

#include <memory>
#include <optional>
#include <thread>
#include <vector>

namespace rs4sim::rpc {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

std::string bytes(const Bytes& b) { return {b.begin(), b.end()}; }
Bytes bytes(const std::string& s) { return {s.begin(), s.end()}; }

// `chars` characters of `bits` bit times at `baud`, in ns (rounded up: the line's clock
// ticks in whole ns, and a frame has arrived only once its last bit has).
std::int64_t wire_ns(int chars, int bits, int baud) {
  return (std::int64_t{chars} * bits * 1'000'000'000LL + baud - 1) / baud;
}

// One device on its simulated line behind a real server, the loop on its own thread.
template <class Device, class Service>
class SimulatedRun : protected TestLoop {
 public:
  SimulatedRun(Device& device, stream::DeviceKind kind, std::uint8_t address,
               std::unique_ptr<Watcher> watcher)
      : tap_(device),
        line_(clock_, tap_),
        target_(std::make_unique<SimulatedLineTarget>(kind, std::move(watcher), line_)),
        service_(LineContext{executor_, clock_, address, tap_, target_->events(), &line_}, device),
        time_(RunContext{*target_, executor_}) {
    tap_.set_hub(target_->events(), address);
    t0_ = clock_.now();
    line_.start();
    start_loop();
    server_ = std::make_unique<RpcServer>(ServerOptions{},
                                          std::vector<grpc::Service*>{&service_, &time_});
    channel_ = grpc::CreateChannel(server_->address(), grpc::InsecureChannelCredentials());
  }
  ~SimulatedRun() {
    server_->shutdown();
    stop_loop();
  }
  SimulatedRun(const SimulatedRun&) = delete;
  SimulatedRun& operator=(const SimulatedRun&) = delete;

  [[nodiscard]] std::int64_t t0_ns() const { return to_ns(t0_); }
  std::shared_ptr<grpc::Channel> channel() { return channel_; }
  std::int64_t now_ns() {
    grpc::ClientContext ctx;
    v1::TimeResponse out;
    EXPECT_TRUE(v1::SimTime::NewStub(channel_)->Now(&ctx, v1::Empty{}, &out).ok());
    EXPECT_TRUE(out.simulated());
    return out.now_ns();
  }

 private:
  stream::ManualClock clock_;
  stream::TimePoint t0_{};
  TappedByteDevice tap_;
  SimulatedLine line_;
  std::unique_ptr<SimulatedLineTarget> target_;
  Service service_;
  SimTimeService time_;
  std::unique_ptr<RpcServer> server_;
  std::shared_ptr<grpc::Channel> channel_;
};

template <class Stub>
v1::ExchangeResponse exchange(Stub& stub, std::uint32_t address, const Bytes& request,
                              std::uint32_t timeout_ms = 0, grpc::Status* status = nullptr) {
  grpc::ClientContext ctx;
  v1::ExchangeRequest in;
  in.set_address(address);
  in.set_request(bytes(request));
  in.set_timeout_ms(timeout_ms);
  v1::ExchangeResponse out;
  const auto s = stub.Exchange(&ctx, in, &out);
  if (status != nullptr) {
    *status = s;
  } else {
    EXPECT_TRUE(s.ok()) << s.error_message();
  }
  return out;
}

template <class Stub>
v1::ReceiveResponse receive(Stub& stub, std::uint32_t address, std::uint32_t wait_ms) {
  grpc::ClientContext ctx;
  v1::ReceiveRequest in;
  in.set_address(address);
  in.set_wait_ms(wait_ms);
  v1::ReceiveResponse out;
  const auto s = stub.Receive(&ctx, in, &out);
  EXPECT_TRUE(s.ok()) << s.error_message();
  return out;
}

// ==== GridScan ==============================================================================

constexpr int kGridScanBaud = 115200;
const Bytes kPowerUpVersion{0x43, 0x45, 0x44, 0x45,              // sync
                            0x00, 0xA0,                          // SeqCnt 0, Info: Get version
                            0x30, 0x31, 0x2E, 0x30, 0x32,        // SW "01.02"
                            0x30, 0x33, 0x2E, 0x30, 0x34,        // HW "03.04"
                            0x33, 0x7F, 0x67, 0x4B};             // CRC
const Bytes kPowerUpReduced{0x43, 0x45, 0x44, 0x45, 0x01, 0xB0,  // SeqCnt 1, Reduced state
                            0x16, 0x00,                          // door 22 open, clear, clean
                            0x69, 0x78, 0x27, 0x24};             // CRC

class GridScanOnTheSimulatedClock : public ::testing::Test {
 protected:
  gridscan::Device device_{gridscan::Options{}};
  SimulatedRun<gridscan::Device, GridScanService> run_{device_, stream::DeviceKind::kGridScan, 0,
                                                       gridscan_watcher(0, device_)};
  std::unique_ptr<v1::GridScan::Stub> stub_ = v1::GridScan::NewStub(run_.channel());

  // The power-up messages from `at`: Get version at once, Reduced state 1700 ms later.
  void expect_power_up(std::int64_t at) {
    const auto got = receive(*stub_, 0, 1702);
    ASSERT_EQ(got.frames_size(), 2);
    EXPECT_EQ(bytes(got.frames(0).frame()), kPowerUpVersion);
    EXPECT_EQ(got.frames(0).start_ns(), at);
    EXPECT_EQ(got.frames(0).end_ns(), at + wire_ns(20, 10, kGridScanBaud));
    EXPECT_EQ(bytes(got.frames(1).frame()), kPowerUpReduced);
    EXPECT_EQ(got.frames(1).start_ns(), at + 1'700'000'000);
  }
  // [GridScan manual §10.3]: the four communication tests, one per 30 ms cycle from `ready`,
  // each request sent when the previous answer is in.
  void expect_the_manuals_exchange(std::int64_t ready) {
    struct Step {
      Bytes request, answer;
    };
    const std::vector<Step> steps{
        {{0x00, 0x00, 0x00, 0x00, 0x00, 0x23, 0x00, 0x00, 0x00, 0x00},  // all wrong
         {0x43, 0x45, 0x44, 0x45, 0x01, 0xA3, 0x07, 0xEF, 0x30, 0x3F, 0x78}},
        {{0x00, 0x00, 0x00, 0x00, 0x02, 0x23, 0x00, 0x00, 0x00, 0x00},  // SeqCnt right
         {0x43, 0x45, 0x44, 0x45, 0x03, 0xA3, 0x05, 0x8F, 0x52, 0x0C, 0x72}},
        {{0x43, 0x45, 0x44, 0x45, 0x04, 0x23, 0x00, 0x00, 0x00, 0x00},  // sync right
         {0x43, 0x45, 0x44, 0x45, 0x05, 0xA3, 0x01, 0x41, 0xCF, 0xDB, 0x65}},
        {{0x43, 0x45, 0x44, 0x45, 0x06, 0x23, 0xE2, 0x4B, 0x01, 0x70},  // CRC right
         {0x43, 0x45, 0x44, 0x45, 0x07, 0xA3, 0x00, 0xF8, 0x8B, 0xAB, 0x62}},
    };
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const auto x = exchange(*stub_, 0, steps[i].request);
      ASSERT_TRUE(x.answered()) << "step " << i;
      EXPECT_EQ(bytes(x.reply()), steps[i].answer) << "step " << i;
      EXPECT_EQ(x.arrived_ns() - x.sent_ns(), wire_ns(10, 10, kGridScanBaud)) << "step " << i;
      // Answered at the end of the cycle the request completed in.
      const std::int64_t cycle_end = ready + 30'000'000LL * static_cast<std::int64_t>(i + 1);
      EXPECT_LT(x.arrived_ns(), cycle_end) << "step " << i;
      EXPECT_EQ(x.reply_start_ns(), cycle_end) << "step " << i;
      EXPECT_EQ(x.reply_end_ns(), cycle_end + wire_ns(11, 10, kGridScanBaud)) << "step " << i;
      EXPECT_EQ(x.reply_after_ns(), x.reply_end_ns() - x.sent_ns());
      EXPECT_EQ(x.now_ns(), x.reply_end_ns());
    }
  }
};

TEST_F(GridScanOnTheSimulatedClock, PowerUpThenTheManualsCommunicationTest) {
  const std::int64_t t0 = run_.t0_ns();
  expect_power_up(t0);
  // 2 ms after ready: the first request completes in cycle 0.
  expect_the_manuals_exchange(t0 + 1'700'000'000);
  EXPECT_EQ(device_.counters().comm_tests, 4U);
}

TEST_F(GridScanOnTheSimulatedClock, PowerCycleRunsThePowerUpAgain) {
  expect_power_up(run_.t0_ns());
  expect_the_manuals_exchange(run_.t0_ns() + 1'700'000'000);
  (void)receive(*stub_, 0, 1000);
  grpc::ClientContext ctx;
  v1::PowerCycleRequest in;
  in.set_off_ms(500);
  v1::Empty none;
  const std::int64_t before = run_.now_ns();
  ASSERT_TRUE(stub_->PowerCycle(&ctx, in, &none).ok());
  const std::int64_t on = before + 500'000'000;
  EXPECT_EQ(run_.now_ns(), on);
  // Before ready (1700 ms after power-on), a request is dropped: no answer.
  const auto early =
      exchange(*stub_, 0, {0x43, 0x45, 0x44, 0x45, 0x02, 0x23, 0xE2, 0x4B, 0x01, 0x70}, 100);
  EXPECT_FALSE(early.answered());
  EXPECT_EQ(device_.counters().not_ready, 1U);
  // The power-up messages again, SeqCnt from 0: the manual's exchange works once more.
  const auto got = receive(*stub_, 0, 1602);
  ASSERT_EQ(got.frames_size(), 2);
  EXPECT_EQ(bytes(got.frames(0).frame()), kPowerUpVersion);
  EXPECT_EQ(got.frames(0).start_ns(), on);
  EXPECT_EQ(bytes(got.frames(1).frame()), kPowerUpReduced);
  EXPECT_EQ(got.frames(1).start_ns(), on + 1'700'000'000);
  expect_the_manuals_exchange(on + 1'700'000'000);
}

TEST_F(GridScanOnTheSimulatedClock, PoweredOffIsSilentUntilOn) {
  expect_power_up(run_.t0_ns());
  grpc::ClientContext off_ctx;
  v1::SetPowerRequest off;
  v1::Empty none;
  ASSERT_TRUE(stub_->SetPower(&off_ctx, off, &none).ok());
  EXPECT_EQ(receive(*stub_, 0, 5000).frames_size(), 0);
  EXPECT_FALSE(
      exchange(*stub_, 0, {0x43, 0x45, 0x44, 0x45, 0x02, 0x23, 0xE2, 0x4B, 0x01, 0x70}).answered());
  grpc::ClientContext on_ctx;
  v1::SetPowerRequest on;
  on.set_on(true);
  const std::int64_t at = run_.now_ns();
  ASSERT_TRUE(stub_->SetPower(&on_ctx, on, &none).ok());
  expect_power_up(at);
}

TEST_F(GridScanOnTheSimulatedClock, BadExchangesAreRefusedWithTheField) {
  grpc::Status s;
  (void)exchange(*stub_, 0, {}, 0, &s);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "request");
  (void)exchange(*stub_, 0, Bytes(257, 0x00), 0, &s);
  EXPECT_EQ(bad_field(s), "request");
  (void)exchange(*stub_, 0, Bytes(256, 0x00), 0, &s);  // the longest: sent, dropped as oversized
  EXPECT_TRUE(s.ok());
  (void)exchange(*stub_, 0, {0x00}, 86'400'001, &s);
  EXPECT_EQ(bad_field(s), "timeout_ms");
  (void)exchange(*stub_, 1, {0x00}, 0, &s);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  grpc::ClientContext ctx;
  v1::PowerCycleRequest cycle;
  cycle.set_off_ms(3'600'001);
  v1::Empty none;
  EXPECT_EQ(bad_field(stub_->PowerCycle(&ctx, cycle, &none)), "off_ms");
}

// ==== Polaris ===============================================================================

constexpr int kPolarisBaud = 19200;
constexpr std::int64_t kT35At19200 = 1'822'917;  // 3.5 characters of 10 bit times: 35 bits

polaris::Options polaris_options(polaris::Family family, std::uint16_t beams,
                                 polaris::DataMode mode, std::uint8_t address) {
  polaris::Options o;
  o.family = family;
  o.beams = beams;
  o.mode = mode;
  o.address = address;
  o.response_time = std::chrono::milliseconds(5);  // one scan (the answer waits for its end)
  return o;
}

std::vector<std::uint16_t> beams(std::initializer_list<std::pair<int, int>> ranges) {
  std::vector<std::uint16_t> out;
  for (const auto& [a, b] : ranges) {
    for (int i = a; i <= b; ++i) out.push_back(static_cast<std::uint16_t>(i));
  }
  return out;
}

struct PolarisCase {
  const char* name;
  polaris::Options options;
  std::vector<std::uint16_t> blocked;
  Bytes request, reply;
};

class PolarisOnTheSimulatedClock : public ::testing::TestWithParam<PolarisCase> {};

TEST_P(PolarisOnTheSimulatedClock, TheManualsFrames) {
  const auto& c = GetParam();
  polaris::Device device(c.options);
  ASSERT_FALSE(device.set_interrupted(c.blocked, stream::ManualClock{}.now()));
  SimulatedRun<polaris::Device, PolarisService> run(
      device, stream::DeviceKind::kPolaris, c.options.address,
      polaris_watcher(c.options.address, device));
  const auto stub = v1::Polaris::NewStub(run.channel());
  const auto x = exchange(*stub, c.options.address, c.request);
  ASSERT_TRUE(x.answered());
  EXPECT_EQ(bytes(x.reply()), c.reply);
  EXPECT_EQ(x.arrived_ns() - x.sent_ns(),
            wire_ns(static_cast<int>(c.request.size()), 10, kPolarisBaud));
  // The answer: no earlier than t3.5 of silence after the request
  // [Modbus serial line V1.02 §2.5.1.1], no later than the end of the scan then (5 ms scans).
  EXPECT_GE(x.reply_start_ns() - x.arrived_ns(), kT35At19200);
  EXPECT_LE(x.reply_start_ns() - x.arrived_ns(),
            kT35At19200 + std::chrono::nanoseconds(c.options.response_time).count());
  EXPECT_EQ(x.reply_end_ns() - x.reply_start_ns(),
            wire_ns(static_cast<int>(c.reply.size()), 10, kPolarisBaud));
  EXPECT_EQ(x.reply_after_ns(), x.reply_end_ns() - x.sent_ns());
}

using polaris::DataMode;
using polaris::Family;
INSTANTIATE_TEST_SUITE_P(
    Manual, PolarisOnTheSimulatedClock,
    ::testing::Values(
        PolarisCase{"P1_P2",
                    polaris_options(Family::kPli02, 127, DataMode::k485Mb, 3),
                    beams({{72, 79}, {87, 92}}),
                    {0x03, 0x03, 0x20, 0x00, 0x00, 0x08, 0x4E, 0x2E},
                    {0x03, 0x03, 0x10, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
                     0x80, 0x7F, 0xF0, 0x3F, 0xFF, 0xFF, 0xFF, 0xFF, 0x1B, 0xD3}},
        PolarisCase{"P3_P4",
                    polaris_options(Family::kPl10, 40, DataMode::kFl4, 1),
                    beams({{9, 13}, {25, 34}}),
                    {0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D},
                    {0x01, 0x03, 0x14, 0x00, 0x09, 0x00, 0x0D, 0x00, 0x19, 0x00, 0x22, 0x00, 0x00,
                     0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x09, 0x00, 0x22, 0x19, 0x5A}},
        PolarisCase{"P3_P5",
                    polaris_options(Family::kPli02, 127, DataMode::kFl4, 1),
                    beams({{68, 71}, {85, 93}}),
                    {0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D},
                    {0x01, 0x03, 0x14, 0x00, 0x44, 0x00, 0x47, 0x00, 0x55, 0x00, 0x5D, 0x00, 0x00,
                     0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x44, 0x00, 0x5D, 0x03, 0xB3}},
        PolarisCase{"P6",
                    polaris_options(Family::kPl10, 40, DataMode::kFl1, 1),
                    beams({{9, 13}, {25, 34}}),
                    {0x01, 0x04, 0x20, 0x00, 0x00, 0x02, 0x7A, 0x0B},
                    {0x01, 0x04, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAB, 0x9F}},
        PolarisCase{"P7",
                    polaris_options(Family::kPl10, 40, DataMode::kFl1, 1),
                    beams({{9, 13}, {25, 34}}),
                    {0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xCB},
                    {0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28}},
        // P1 with its CRC's bytes swapped -> P8: FC 3|0x80, exception 07.
        PolarisCase{"P8",
                    polaris_options(Family::kPli02, 127, DataMode::k485Mb, 3),
                    {},
                    {0x03, 0x03, 0x20, 0x00, 0x00, 0x08, 0x2E, 0x4E},
                    {0x03, 0x83, 0x07, 0xA1, 0x32}}),
    [](const ::testing::TestParamInfo<PolarisCase>& i) { return std::string(i.param.name); });

TEST(PolarisOnTheSimulatedClockSilence, ABroadcastGetsNoReplyWithinTheTimeout) {
  polaris::Device device(polaris_options(Family::kPl10, 40, DataMode::kFl1, 1));
  SimulatedRun<polaris::Device, PolarisService> run(device, stream::DeviceKind::kPolaris, 1,
                                                    polaris_watcher(1, device));
  const auto stub = v1::Polaris::NewStub(run.channel());
  const std::int64_t before = run.now_ns();
  // Slave 0 (broadcast), FC 3: never answered [Modbus serial line V1.02 §2.1].
  const auto x = exchange(*stub, 1, {0x00, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCE, 0x1A}, 200);
  EXPECT_FALSE(x.answered());
  EXPECT_TRUE(x.reply().empty());
  EXPECT_EQ(x.now_ns(), before + 200'000'000);
  EXPECT_EQ(device.counters().broadcasts, 1U);
}

// Exchange and Receive take the Modbus slave addresses only (1..247
// [Modbus serial line V1.02 §2.2]), then this run's address alone.
TEST(PolarisOnTheSimulatedClockAddress, ExchangeAndReceiveCheckTheModbusAddress) {
  polaris::Device device(polaris_options(Family::kPl10, 40, DataMode::kFl1, 1));
  SimulatedRun<polaris::Device, PolarisService> run(device, stream::DeviceKind::kPolaris, 1,
                                                    polaris_watcher(1, device));
  const auto stub = v1::Polaris::NewStub(run.channel());
  const Bytes request{0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xCB};
  for (const std::uint32_t address : {0U, 248U}) {
    grpc::Status s;
    (void)exchange(*stub, address, request, 0, &s);
    EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << address;
    EXPECT_EQ(s.error_message(), "address: " + std::to_string(address) +
                                     " outside 1..247, the Modbus slave addresses "
                                     "[Modbus serial line V1.02 §2.2]");
    grpc::ClientContext ctx;
    v1::ReceiveRequest in;
    in.set_address(address);
    v1::ReceiveResponse out;
    EXPECT_EQ(bad_field(stub->Receive(&ctx, in, &out)), "address") << address;
  }
  grpc::Status s;
  (void)exchange(*stub, 2, request, 0, &s);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(s.error_message(), "no Polaris at address 2 (this run's Polaris answers to 1)");
  EXPECT_EQ(device.counters().requests, 0U);  // nothing reached the line
}

// ==== METRON ================================================================================

constexpr int kMetronBaud = 19200;  // 8E1: 11 bit times a character

struct MetronCase {
  const char* name;
  Bytes request, reply;
};

class MetronOnTheSimulatedClock : public ::testing::TestWithParam<MetronCase> {};

TEST_P(MetronOnTheSimulatedClock, TheErrorAnswers) {
  const auto& c = GetParam();
  metron::Device device(metron::Options{});
  SimulatedRun<metron::Device, MetronService> run(device, stream::DeviceKind::kMetron, 0,
                                                    metron_watcher(0, device));
  const auto stub = v1::Metron::NewStub(run.channel());
  const auto x = exchange(*stub, 0, c.request);
  ASSERT_TRUE(x.answered());
  EXPECT_EQ(bytes(x.reply()), c.reply);
  EXPECT_EQ(x.arrived_ns() - x.sent_ns(),
            wire_ns(static_cast<int>(c.request.size()), 11, kMetronBaud));
  EXPECT_GT(x.reply_start_ns(), x.arrived_ns());
  EXPECT_LE(x.reply_start_ns() - x.arrived_ns(), 20'000'000);  // t_response
  EXPECT_EQ(x.reply_end_ns() - x.reply_start_ns(),
            wire_ns(static_cast<int>(c.reply.size()), 11, kMetronBaud));
}

// STX 0x02, length, command, data, checksum; the error replies 0xE1..0xE5 are the project's
// EXTENSION values (metron/wire_table.h).
INSTANTIATE_TEST_SUITE_P(
    Manual, MetronOnTheSimulatedClock,
    ::testing::Values(
        MetronCase{"E1_wrong_checksum", {0x02, 0x01, 0x0C, 0xF4}, {0x02, 0x01, 0xE1, 0x1E}},
        MetronCase{"E2_wrong_length", {0x02, 0x02, 0x0C, 0x00, 0xF3}, {0x02, 0x01, 0xE2, 0x1D}},
        MetronCase{"E2_no_such_command", {0x02, 0x01, 0x77, 0x88}, {0x02, 0x01, 0xE2, 0x1D}},
        MetronCase{
            "E3_stop_ossd_without_start", {0x02, 0x01, 0x06, 0xF9}, {0x02, 0x01, 0xE3, 0x1C}},
        MetronCase{"E5_stop_measurement_without_start",
                   {0x02, 0x01, 0x08, 0xF7},
                   {0x02, 0x01, 0xE5, 0x1A}}),
    [](const ::testing::TestParamInfo<MetronCase>& i) { return std::string(i.param.name); });

TEST(MetronOnTheSimulatedClockSync, E4WhenTheSynchronismIsLost) {
  metron::Device device(metron::Options{});
  SimulatedRun<metron::Device, MetronService> run(device, stream::DeviceKind::kMetron, 0,
                                                    metron_watcher(0, device));
  const auto stub = v1::Metron::NewStub(run.channel());
  grpc::ClientContext ctx;
  v1::SetSynchronisedRequest in;  // false
  v1::Empty none;
  ASSERT_TRUE(stub->SetSynchronised(&ctx, in, &none).ok());
  const auto x = exchange(*stub, 0, {0x02, 0x02, 0x07, 0x01, 0xF7});  // #7
  ASSERT_TRUE(x.answered());
  EXPECT_EQ(bytes(x.reply()), (Bytes{0x02, 0x01, 0xE4, 0x1B}));
}

}  // namespace
}  // namespace rs4sim::rpc

namespace rs4sim::rpc {
namespace {

// The input type in slave mode: with enable-line the host may not drive the OSSDs (#2..#6 get
// E2), and the configuration (#11) reports type 1 [METRON manual "Slave line mode"].
TEST(MetronInputOnTheSimulatedClock, SlaveModeWithAnInputType) {
  metron::Options o;
  o.input_type = metron::InputType::kEnableLine;
  metron::Device device(o);
  SimulatedRun<metron::Device, MetronService> run(device, stream::DeviceKind::kMetron, 0,
                                                    metron_watcher(0, device));
  const auto stub = v1::Metron::NewStub(run.channel());
  // #11: beams 24, input type 1, node 0, scan cycle 10 ms, t_response 20 ms; checksum: the
  // bytes from the length on sum to 0 mod 256.
  auto x = exchange(*stub, 0, {0x02, 0x01, 0x0B, 0xF4});
  EXPECT_EQ(bytes(x.reply()), (Bytes{0x02, 0x06, 0x0B, 0x18, 0x01, 0x00, 0x0A, 0x14, 0xBD}));
  x = exchange(*stub, 0, {0x02, 0x01, 0x03, 0xFC});  // #3 disable OSSD
  EXPECT_EQ(bytes(x.reply()), (Bytes{0x02, 0x01, 0xE2, 0x1D}));
}

// Input-related reporting with enable-line: reports only while the input is high.
TEST(MetronInputOnTheSimulatedClock, StandardModeReportsWhileTheInputIsHigh) {
  metron::Options o;
  o.line_mode = metron::LineMode::kStandard;
  o.reporting_mode = metron::ReportingMode::kInputRelated;
  o.input_type = metron::InputType::kEnableLine;
  metron::Device device(o);
  const std::vector<std::uint16_t> blocked{9, 10, 11, 12, 13};
  device.set_interrupted(blocked);
  SimulatedRun<metron::Device, MetronService> run(device, stream::DeviceKind::kMetron, 0,
                                                    metron_watcher(0, device));
  const auto stub = v1::Metron::NewStub(run.channel());
  EXPECT_EQ(receive(*stub, 0, 100).frames_size(), 0);
  const auto set_input = [&](bool high) {
    grpc::ClientContext ctx;
    v1::SetInputRequest in;
    in.set_high(high);
    v1::Empty none;
    ASSERT_TRUE(stub->SetInput(&ctx, in, &none).ok());
  };
  set_input(true);
  const auto got = receive(*stub, 0, 35);  // scan cycles of 10 ms: 3 or 4 reports
  ASSERT_GE(got.frames_size(), 3);
  ASSERT_LE(got.frames_size(), 4);
  for (const auto& f : got.frames()) {
    EXPECT_EQ(bytes(f.frame()), (Bytes{0x02, 0x09, 0x0D, 0x05, 0x03}));  // first, last, count
    EXPECT_EQ(f.end_ns() - f.start_ns(), wire_ns(5, 11, kMetronBaud));
  }
  grpc::ClientContext ctx;
  v1::LineDeviceRequest req;
  v1::MetronState state;
  ASSERT_TRUE(stub->GetState(&ctx, req, &state).ok());
  EXPECT_TRUE(state.input_high());
  EXPECT_EQ(state.input_type(), "enable-line");
  set_input(false);
  (void)receive(*stub, 0, 5);  // a report already on the line
  EXPECT_EQ(receive(*stub, 0, 100).frames_size(), 0);
}

}  // namespace
}  // namespace rs4sim::rpc
