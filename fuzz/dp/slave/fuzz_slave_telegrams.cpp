// libFuzzer target: arbitrary telegram sequences into a dp::slave::Slave with a FakeApplication,
// time advanced from the input. Invariants ([IEC 61158-4-3 frame reception]
// [IEC 61158-6-3 Slave_Diag]):
//   * never a reply to DA 127 or to an SDN request, at most one reply per request;
//   * every reply encodes, decodes back to itself and is addressed to the requester;
//   * the diagnosis never exceeds max_diag_length and never carries master-only bits;
//   * nothing crashes or hangs (ASan/UBSan).
//
// Input = records. Record op = byte & 3:
//   0 raw frame:   [op][n][n bytes]           → fdl::decode_frame → on_telegram if valid
//   1 time:        [op][lo][hi]               → advance (lo|hi<<8)·100 µs, on_time if due
//   2 application: [op][what][arg]            → submit alarm / device diag / complete
//   3 telegram:    [op][da][sa][fc][saps][len][len bytes] → built directly (deep states)
#include "dp/fdl/decoder.h"
#include "dp/fdl/telegram.h"
#include "dp/slave/slave.h"
#include "tests/dp/slave/fake_application.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

using namespace rs4sim::dp;
namespace dp = rs4sim::dp;

namespace {

void require(bool ok) {
  if (!ok) std::abort();
}

void check_reply(const dp::slave::Slave& slave, const fdl::Telegram& req,
                 const fdl::Telegram& reply) {
  std::vector<std::uint8_t> wire;
  fdl::encode(reply, wire);  // throws (→ libFuzzer crash report) if malformed
  fdl::Telegram back;
  require(!fdl::decode_frame(wire, back));
  require(back == reply);
  if (reply.type != fdl::FrameType::kShortAck) {
    require(reply.da == req.sa);
    require(!reply.fc.is_request());
    require(reply.sa <= 126);
  }
  (void)slave;
}

void deliver(dp::slave::Slave& slave, const fdl::Telegram& t, TimePoint now) {
  slave.on_telegram(t, now);
  auto reply = slave.take_transmit();
  require(!slave.take_transmit().has_value());
  const auto f = t.fc.function();
  const bool sdn = f == fdl::RequestFunction::kSdnLow || f == fdl::RequestFunction::kSdnHigh;
  if (t.da == fdl::kBroadcastAddress || (t.fc.is_request() && sdn)) require(!reply.has_value());
  if (reply) check_reply(slave, t, *reply);
  const auto diag = slave.diagnosis();
  require(diag.size() >= 6 && diag.size() <= 244);
  require((diag[0] & 0xA1) == 0 && (diag[1] & 0x84) == 0x04);
}

void app_action(dp::slave::Slave& slave, rs4sim::dp::testing::FakeApplication& app,
                std::uint8_t what, std::uint8_t arg) {
  static const std::uint8_t kData[8] = {0x84, 0x24, 0x18, 0x00, 0x01, 0x00, 0x00, 0x00};
  switch (what % 5) {
    case 0:
      (void)slave.submit_alarm({static_cast<std::uint8_t>(arg % 8), 0,
                                static_cast<std::uint8_t>(arg >> 6), true,
                                std::span(kData, arg % 9)});
      break;
    case 1:
      (void)slave.set_device_diagnosis(std::span(kData, arg % 9), (arg & 1) != 0, (arg & 2) != 0);
      break;
    case 2:
      (void)slave.complete_acyclic(dp::slave::AcyclicChannel::kC1,
                                   dp::slave::AcyclicResult::ok(std::span(kData, arg % 9)));
      break;
    case 3:
      (void)slave.complete_acyclic(
          dp::slave::AcyclicChannel::kC2,
          dp::slave::AcyclicResult::fail({0x80, dp::pdu::ErrorCode1{arg}, 0}));
      break;
    default:
      app.acyclic_mode = static_cast<rs4sim::dp::testing::FakeApplication::AcyclicMode>(arg % 3);
      app.prm_verdict = static_cast<dp::slave::PrmVerdict>((arg >> 2) % 3);
      break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rs4sim::dp::testing::FakeApplication app;
  dp::slave::Config cfg;
  cfg.address = 5;
  cfg.ident_number = 0x1234;
  cfg.dpv1 = true;
  cfg.sync_supported = cfg.freeze_supported = cfg.set_slave_add_supported = true;
  cfg.fail_safe_supported = cfg.c2_supported = true;
  cfg.max_diag_length = size > 0 && (data[0] & 0x80) ? 16 : 244;
  dp::slave::Slave slave(cfg, app);
  ManualClock clock;
  std::size_t i = 0;
  const auto take = [&](std::size_t n) -> std::span<const std::uint8_t> {
    n = std::min(n, size - i);
    std::span<const std::uint8_t> s(data + i, n);
    i += n;
    return s;
  };
  while (i < size) {
    const std::uint8_t op = data[i++];
    if ((op & 3) == 0) {
      const auto n = take(1);
      const auto frame = take(n.empty() ? 0 : n[0]);
      fdl::Telegram t;
      if (!fdl::decode_frame(frame, t)) deliver(slave, t, clock.now());
    } else if ((op & 3) == 1) {
      const auto b = take(2);
      const unsigned ticks = b.size() == 2 ? static_cast<unsigned>(b[0] | (b[1] << 8)) : 0U;
      clock.advance(std::chrono::microseconds(100) * ticks);
      const auto d = slave.next_deadline();
      if (d && clock.now() >= *d) slave.on_time(clock.now());
    } else if ((op & 3) == 2) {
      const auto b = take(2);
      if (b.size() == 2) app_action(slave, app, b[0], b[1]);
    } else {
      const auto h = take(5);
      if (h.size() < 5) break;
      fdl::Telegram t;
      t.da = (h[0] & 0x80) ? static_cast<std::uint8_t>(h[0] & 0x7F) : 5;
      t.sa = h[1] & 0x7F;
      t.fc.raw = static_cast<std::uint8_t>((h[2] & 0x3F) | 0x40);
      if ((h[3] & 0x80) == 0) {
        t.dsap = static_cast<std::uint8_t>(h[3] & 0x3F);
        t.ssap = static_cast<std::uint8_t>((h[3] & 0x40) ? 51 : 62);
      }
      const auto du = take(std::min<std::size_t>(h[4], fdl::kMaxDataUnit - 2));
      t.data.assign(du.begin(), du.end());
      t.type = t.data.empty() && !t.dsap ? fdl::FrameType::kSd1 : fdl::FrameType::kSd2;
      deliver(slave, t, clock.now());
    }
  }
  return 0;
}
