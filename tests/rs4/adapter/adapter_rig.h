#pragma once
// Test rig: one Adapter driven through its dp::slave::SlaveApplication calls, a fake
// SlaveControl that records alarms and diagnosis, and a real profisafe::FHost producing
// the F-output PDUs. Time is a manual clock (no sleeps).

#include "profisafe/f_host.h"
#include "rs4/adapter/adapter.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/adapter/rs4_gsd.h"
#include "rs4/protocol/block.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <vector>

namespace rs4sim::rs4::adapter::testing {

using Bytes = std::vector<std::uint8_t>;

using namespace std::chrono_literals;

struct RecordedAlarm {
  std::uint8_t type = 0, slot = 0, specifier = 0;
  bool add_ack = false;
  std::vector<std::uint8_t> user_data;
};

class FakeControl final : public dp::slave::SlaveControl {
 public:
  std::error_code complete_acyclic(dp::slave::AcyclicChannel,
                                   const dp::slave::AcyclicResult&) override {
    return {};
  }
  std::error_code submit_alarm(const dp::slave::AlarmRequest& a) override {
    alarms.push_back({a.type, a.slot, a.specifier, a.add_ack,
                      std::vector<std::uint8_t>(a.user_data.begin(), a.user_data.end())});
    return {};
  }
  std::error_code set_device_diagnosis(std::span<const std::uint8_t> blocks, bool ext,
                                       bool stat) override {
    diagnosis.assign(blocks.begin(), blocks.end());
    ext_diag = ext;
    stat_diag = stat;
    return {};
  }
  std::vector<RecordedAlarm> alarms;
  std::vector<std::uint8_t> diagnosis;
  bool ext_diag = false, stat_diag = false;
};

inline profisafe::FParameters rs4_fparams(std::uint16_t dest = 504) {
  profisafe::FParameters p;
  p.dest_add = dest;
  p.source_add = 1;
  p.wd_time_ms = 1000;
  return p;
}

// User_Prm_Data after the DPV1 bytes (docs/gsd.md): 0E 05 01 00 + the F-parameter block.
inline dp::pdu::SetPrm set_prm_for(const profisafe::FParameters& p) {
  dp::pdu::SetPrm prm;
  prm.ident_number = ident_number();
  for (auto b : kFBlockHeader) prm.user_data.push_back(b);
  for (auto b : profisafe::encode_f_parameters(p)) prm.user_data.push_back(b);
  return prm;
}

struct Rig {
  explicit Rig(AdapterConfig cfg = {}, profisafe::FParameters fp = rs4_fparams())
      : adapter(cfg), host(profisafe::FHostConfig{fp, 1, {}}), params(fp) {
    adapter.on_attach(control);
  }
  dp::TimePoint now{};
  Adapter adapter;
  FakeControl control;
  profisafe::FHost host;
  profisafe::FParameters params;
  std::uint8_t out_byte = 0x01;  // field pair 1, Proxy-Enable 0, restart 0

  void advance(std::chrono::milliseconds d) {
    const auto end = now + d;
    while (true) {
      auto next = adapter.next_deadline();
      if (!next || *next > end) break;
      now = std::max(now, *next);
      adapter.on_time(now);
    }
    now = end;
    adapter.on_time(now);
  }
  // Power on, wait for the adapter init, start DP (Set_Prm, Chk_Cfg, Data_Exch).
  void start(bool power = true) {
    if (power) adapter.power_on(now);
    advance(3s);
    ASSERT_EQ(adapter.check_parameters(set_prm_for(params), now), dp::slave::PrmVerdict::kAccept);
    ASSERT_EQ(adapter.check_config(kRealConfig, false, now), dp::slave::CfgVerdict::kAccept);
    adapter.on_state_change(dp::slave::State::kWaitCfg, dp::slave::State::kDataExch,
                            dp::slave::TransitionReason::kCfgAccepted, now);
  }
  // One Data_Exchange: FHost PDU → adapter → F-input PDU → FHost.
  void cycle() {
    host.set_output(std::span<const std::uint8_t>(&out_byte, 1));
    const auto req = host.request(now);
    const std::vector<std::uint8_t> pdu(req.begin(), req.end());
    adapter.on_outputs(pdu, now);
    std::array<std::uint8_t, kPduSize> in{};
    adapter.read_inputs(in, now);
    host.on_pdu(in, now);
  }
  // Cyclic exchange every `step` for `d`, the adapter's own timers in between.
  void run(std::chrono::milliseconds d, std::chrono::milliseconds step = 20ms) {
    for (auto t = 0ms; t < d; t += step) {
      advance(step);
      cycle();
    }
  }
  // The process byte as the F-host sees it (substitute 0 while passivated).
  [[nodiscard]] std::uint8_t host_input() const { return host.input()[0]; }
  [[nodiscard]] bool ossd() const { return (host_input() & kInputOssd) != 0; }
  // Powered, parametrised, 31 s of cycles (the RS4 measures after its ≈30 s boot
  // [RS4 manual §7.1.1]) and a restart pulse: whether the OSSD is on.
  [[nodiscard]] bool boot_and_release() {
    start();
    run(31s);
    restart_pulse();
    return ossd();
  }
  void restart_pulse(std::chrono::milliseconds length = 200ms) {
    out_byte = static_cast<std::uint8_t>(out_byte | kOutputRestart);
    run(length);
    out_byte = static_cast<std::uint8_t>(out_byte & ~kOutputRestart);
    run(100ms);
  }

  // ---- acyclic ----
  dp::slave::AcyclicResult write(std::vector<std::uint8_t> record, std::uint8_t index = 2,
                                 dp::slave::AcyclicChannel ch = dp::slave::AcyclicChannel::kC1,
                                 bool first_c2 = false) {
    dp::slave::AcyclicRequest r;
    r.channel = ch;
    r.service = dp::slave::AcyclicService::kWrite;
    r.index = index;
    r.length = static_cast<std::uint8_t>(record.size());
    r.data = record;
    r.first_write_after_initiate = first_c2;
    return adapter.on_acyclic(r, now);
  }
  dp::slave::AcyclicResult read(std::uint8_t length = 240,
                                dp::slave::AcyclicChannel ch = dp::slave::AcyclicChannel::kC1,
                                std::uint8_t slot = 0, std::uint8_t index = 3) {
    dp::slave::AcyclicRequest r;
    r.channel = ch;
    r.service = dp::slave::AcyclicService::kRead;
    r.slot = slot;
    r.index = index;
    r.length = length;
    return adapter.on_acyclic(r, now);
  }
  // A single-block command: 00 len FF FF payload.
  static std::vector<std::uint8_t> block(std::vector<std::uint8_t> payload,
                                         std::uint16_t number = 0xFFFF) {
    std::vector<std::uint8_t> r(payload.size() + 4);
    r[0] = 0x00;
    r[1] = static_cast<std::uint8_t>(payload.size() + 4);
    r[2] = static_cast<std::uint8_t>(number >> 8);
    r[3] = static_cast<std::uint8_t>(number & 0xFF);
    for (std::size_t i = 0; i < payload.size(); ++i) r[i + 4] = payload[i];
    return r;
  }
  // Reads all blocks of one answer; returns the payload, checks numbering. While the RS4 still
  // works on the command (header only, an answer pending), it polls every 10 ms as a master
  // does ([RS4 manual §5.2.1]); `polls` counts those READs.
  std::vector<std::uint8_t> read_answer(
      std::uint8_t length = 240, dp::slave::AcyclicChannel ch = dp::slave::AcyclicChannel::kC1) {
    std::vector<std::uint8_t> payload;
    polls = 0;
    for (unsigned n = 0; n < 100;) {
      const auto r = read(length, ch);
      EXPECT_EQ(r.kind, dp::slave::AcyclicResult::Kind::kData);
      if (n == 0 && r.data.size() == 4 && adapter.pending_answers(ch) > 0 && polls < 20000) {
        ++polls;
        advance(10ms);
        continue;
      }
      ++n;
      if (r.data.size() < 4) return payload;
      payload.insert(payload.end(), r.data.begin() + 4, r.data.end());
      if (r.data[2] == 0xFF && r.data[3] == 0xFF) return payload;
      EXPECT_EQ((r.data[2] << 8) | r.data[3], static_cast<int>(n - 1));
    }
    return payload;
  }
  unsigned polls = 0;  // READs of the last read_answer() that found the RS4 still processing
  [[nodiscard]] std::size_t alarms_of(std::uint8_t type, std::uint8_t specifier) const {
    std::size_t n = 0;
    for (const auto& a : control.alarms) n += (a.type == type && a.specifier == specifier) ? 1 : 0;
    return n;
  }
};

}  // namespace rs4sim::rs4::adapter::testing
