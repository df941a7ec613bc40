#pragma once
// A recording SlaveApplication for the slave tests, the fuzzer and the benchmark.
// Everything it is asked is logged; every answer is configurable.

#include "dp/slave/slave_application.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <optional>
#include <vector>

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test

using Bytes = std::vector<std::uint8_t>;

class FakeApplication : public SlaveApplication {
 public:
  // --- configurable answers ---
  // (built from arrays: gcc 12 warns falsely on initializer-list members at -O2)
  // 1 byte in, 1 byte out ([docs/references.md#dp-worked-example])
  static constexpr std::uint8_t kConfig[] = {0x10, 0x20};
  static constexpr std::uint8_t kInputs[] = {0x3C};
  static constexpr std::uint8_t kReadData[] = {0xAB, 0xCD};
  Bytes config{std::begin(kConfig), std::end(kConfig)};
  Bytes inputs{std::begin(kInputs), std::end(kInputs)};
  PrmVerdict prm_verdict = PrmVerdict::kAccept;
  std::optional<CfgVerdict> cfg_verdict;  // default: accept iff Chk_Cfg == config
  enum class AcyclicMode { kData, kError, kPending } acyclic_mode = AcyclicMode::kData;
  Bytes read_data{std::begin(kReadData), std::end(kReadData)};
  AcyclicError acyclic_error{0x80, dp::pdu::ErrorCode1{0xB0}, 0x00};
  std::optional<TimePoint> deadline;

  // --- recorded calls ---
  SlaveControl* control = nullptr;
  std::vector<Bytes> outputs;
  std::vector<OutputClear> clears;
  struct Transition {
    State from, to;
    TransitionReason why;
  };
  std::vector<Transition> transitions;
  struct Acyclic {
    AcyclicRequest req;
    Bytes data;
  };
  std::vector<Acyclic> acyclic;
  std::vector<AlarmAck> acks;
  std::vector<C2Event> c2_events;
  std::vector<std::uint8_t> new_addresses;
  std::vector<Bytes> user_prm;
  bool last_user_check = false;
  int time_calls = 0;

  void on_attach(SlaveControl& c) override { control = &c; }
  PrmVerdict check_parameters(const pdu::SetPrm& prm, TimePoint) override {
    user_prm.emplace_back(prm.user_data.begin(), prm.user_data.end());
    return prm_verdict;
  }
  CfgVerdict check_config(std::span<const std::uint8_t> cfg, bool user_check, TimePoint) override {
    last_user_check = user_check;
    if (cfg_verdict) return *cfg_verdict;
    return Bytes(cfg.begin(), cfg.end()) == config ? CfgVerdict::kAccept : CfgVerdict::kCfgFault;
  }
  [[nodiscard]] std::span<const std::uint8_t> real_config() const override { return config; }
  void on_outputs(std::span<const std::uint8_t> o, TimePoint) override {
    outputs.emplace_back(o.begin(), o.end());
  }
  void on_outputs_cleared(OutputClear why, TimePoint) override { clears.push_back(why); }
  void read_inputs(std::span<std::uint8_t> in, TimePoint) override {
    for (std::size_t i = 0; i < in.size(); ++i) in[i] = i < inputs.size() ? inputs[i] : 0;
  }
  void on_state_change(State from, State to, TransitionReason why, TimePoint) override {
    transitions.push_back({from, to, why});
  }
  AcyclicResult on_acyclic(const AcyclicRequest& req, TimePoint) override {
    acyclic.push_back({req, Bytes(req.data.begin(), req.data.end())});
    switch (acyclic_mode) {
      case AcyclicMode::kData:
        if (req.service == AcyclicService::kWrite) return AcyclicResult::ok();
        return AcyclicResult::ok(std::span<const std::uint8_t>(
            read_data.data(), std::min<std::size_t>(read_data.size(), req.length)));
      case AcyclicMode::kError: return AcyclicResult::fail(acyclic_error);
      case AcyclicMode::kPending: break;
    }
    return AcyclicResult::pending();
  }
  void on_alarm_acknowledged(const AlarmAck& a, TimePoint) override { acks.push_back(a); }
  void on_c2_event(C2Event ev, std::uint8_t, TimePoint) override { c2_events.push_back(ev); }
  void on_address_changed(std::uint8_t a, bool, std::span<const std::uint8_t>, TimePoint) override {
    new_addresses.push_back(a);
  }
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override { return deadline; }
  void on_time(TimePoint) override {
    ++time_calls;
    deadline.reset();
  }
};

}  // namespace rs4sim::dp::testing
