// libFuzzer target: a class 1 master with three slaves fed arbitrary replies, time steps
// and user requests. It must never crash, never transmit a telegram the FDL codec
// rejects or does not round-trip, never send more than one telegram per call outside the
// token claim, never transmit a response, and always report a deadline in the future
// after on_time() (no livelock).
//
// Input: a sequence of operations, op = byte & 7:
//   0 advance to next_deadline(), on_time     1 advance u16 µs, on_time
//   2 raw frame: len, bytes → decode_frame → on_telegram
//   3 shaped reply to the last request: kind, status, len, DU
//   4 read(slave, slot, index, length)        5 write(slave, slot, index, len, data)
//   6 user: outputs / Global_Control / mode / alarm ack   7 short acknowledgement E5

#include "dp/fdl/decoder.h"
#include "dp/fdl/telegram.h"
#include "dp/master/master.h"

#include <cstdint>
#include <cstdlib>
#include <span>
#include <stdexcept>
#include <vector>

namespace {

using namespace rs4sim::dp;
using namespace rs4sim::dp::master;

class Input {
 public:
  explicit Input(std::span<const std::uint8_t> d) : d_(d) {}
  bool empty() const { return pos_ >= d_.size(); }
  std::uint8_t u8() { return pos_ < d_.size() ? d_[pos_++] : 0; }
  std::uint16_t u16() { return static_cast<std::uint16_t>(u8() << 8 | u8()); }
  std::span<const std::uint8_t> bytes(std::size_t n) {
    n = std::min(n, d_.size() - std::min(pos_, d_.size()));
    auto s = d_.subspan(pos_, n);
    pos_ += n;
    return s;
  }

 private:
  std::span<const std::uint8_t> d_;
  std::size_t pos_ = 0;
};

SlaveEntry slave(std::uint8_t address, bool dpv1, std::uint8_t alarm_mode, bool extra_sap,
                 std::size_t in, std::size_t out) {
  SlaveEntry s;
  s.address = address;
  s.prm.station_status.lock_req = true;
  s.prm.ident_number = 0x1234;
  if (dpv1) {
    pdu::Dpv1Status d;
    d.dpv1_enable = true;
    d.enable_diagnostic_alarm = true;
    d.enable_process_alarm = true;
    d.alarm_mode = alarm_mode;
    s.prm.dpv1 = d;
  }
  if (in > 0) s.cfg.push_back(static_cast<std::uint8_t>(0x10 | (in - 1)));
  if (out > 0) s.cfg.push_back(static_cast<std::uint8_t>(0x20 | (out - 1)));
  if (s.cfg.empty()) s.cfg.push_back(0x00);
  s.input_length = in;
  s.output_length = out;
  s.extra_alarm_sap = extra_sap;
  s.c1_response_timeout = std::chrono::milliseconds(30);
  return s;
}

struct Harness {
  TimePoint now{std::chrono::hours(1)};
  Master master;
  fdl::Telegram last_request;

  explicit Harness(bool claim_token) : master(config(claim_token)) {}

  static MasterConfig config(bool claim_token) {
    MasterConfig m;
    m.address = 2;
    m.claim_token = claim_token;
    m.cycle_target = std::chrono::milliseconds(2);
    m.global_control_interval = std::chrono::milliseconds(7);
    m.ready_timeout = std::chrono::milliseconds(20);
    m.slaves = {slave(5, true, 0, false, 1, 1), slave(6, false, 0, false, 0, 2),
                slave(7, true, 3, true, 4, 0)};
    return m;
  }

  void check_transmit(bool token_phase) {
    int n = 0;
    while (auto t = master.take_transmit()) {
      ++n;
      std::vector<std::uint8_t> wire;
      try {
        fdl::encode(*t, wire);
      } catch (const std::invalid_argument&) {
        std::abort();  // malformed telegram
      }
      fdl::Telegram back;
      if (fdl::decode_frame(wire, back) || !(back == *t)) std::abort();
      if (t->type != fdl::FrameType::kToken && !t->fc.is_request()) std::abort();
      if (t->sa != 2) std::abort();
      if (t->type != fdl::FrameType::kToken) last_request = *t;
    }
    if (n > (token_phase ? 2 : 1)) std::abort();
  }

  void time(TimePoint t) {
    now = std::max(now, t);
    const bool token_phase = master.phase() != MasterPhase::kRunning;
    master.on_time(now);
    check_transmit(token_phase);
    if (auto d = master.next_deadline(); !d || *d <= now) std::abort();  // livelock
  }

  void deliver(const fdl::Telegram& t) {
    master.on_telegram(t, now);
    check_transmit(false);
  }

  void shaped_reply(Input& in) {
    const std::uint8_t kind = in.u8();
    const auto status = static_cast<fdl::ResponseStatus>(in.u8() & 0x0F);
    const auto du = in.bytes(std::min<std::size_t>(in.u8(), 200));
    const auto fc = fdl::FrameControl::response(status);
    const std::uint8_t from = last_request.da;
    switch (kind & 3) {
      case 0:
        if (last_request.dsap) {
          deliver(fdl::make_data_telegram(2, from, fc, last_request.ssap, last_request.dsap, du));
          return;
        }
        [[fallthrough]];
      case 1: deliver(fdl::make_data_telegram(2, from, fc, std::nullopt, std::nullopt, du)); return;
      case 2: deliver(fdl::make_data_telegram(2, from, fc, std::nullopt, std::nullopt, {})); return;
      default: deliver(fdl::make_token(2, from & 0x7F)); return;
    }
  }

  void user(Input& in) {
    const std::uint8_t what = in.u8();
    const std::uint8_t address = static_cast<std::uint8_t>(4 + (in.u8() & 3));  // 4..7
    switch (what & 3) {
      case 0: {
        const auto out = in.bytes(in.u8() & 3);
        (void)master.set_outputs(address, out);
        return;
      }
      case 1: {
        pdu::GlobalControl gc;
        const std::uint8_t cmd = in.u8();
        gc.clear_data = cmd & 0x02;
        gc.freeze = cmd & 0x08;
        gc.sync = cmd & 0x20;
        gc.reserved = static_cast<std::uint8_t>(cmd & 0xC1);
        gc.group_select = in.u8();
        (void)master.global_control(gc);
        return;
      }
      case 2:
        master.set_operating_mode((what & 4) ? OperatingMode::kClear : OperatingMode::kOperate);
        return;
      default: (void)master.acknowledge_alarm(address, in.u8(), in.u8(), in.u8() & 31); return;
    }
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in({data, size});
  Harness h((size > 0) && (data[0] & 0x80));
  std::vector<MasterEvent> events;
  while (!in.empty()) {
    const std::uint8_t op = in.u8();
    switch (op & 7) {
      case 0: h.time(h.master.next_deadline().value_or(h.now)); break;
      case 1: h.time(h.now + std::chrono::microseconds(in.u16())); break;
      case 2: {
        const auto frame = in.bytes(in.u8());
        fdl::Telegram t;
        if (!fdl::decode_frame(frame, t)) h.deliver(t);
        break;
      }
      case 3: h.shaped_reply(in); break;
      case 4: {
        const std::uint8_t a = static_cast<std::uint8_t>(4 + (in.u8() & 3));
        (void)h.master.read(a, in.u8(), in.u8(), in.u8());
        break;
      }
      case 5: {
        const std::uint8_t a = static_cast<std::uint8_t>(4 + (in.u8() & 3));
        const std::uint8_t slot = in.u8(), index = in.u8();
        (void)h.master.write(a, slot, index, in.bytes(in.u8()));
        break;
      }
      case 6: h.user(in); break;
      default: h.deliver(fdl::make_short_ack()); break;
    }
    h.master.take_events(events);
    events.clear();
    for (std::uint8_t a = 4; a <= 7; ++a) (void)h.master.slave_status(a);
  }
  return 0;
}
