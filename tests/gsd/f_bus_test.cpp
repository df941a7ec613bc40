// GSD F-devices with our master's F-hosts on the simulated bus (gsd::GsdMasterSlaves), the
// way `rs4sim run --gsd FILE --link memory` runs them: a V1 station (corpus/f_module_v1.gsd, the
// drive's "PROFIsafe v1.x Module", F_WD_Time 100 ms) at address 5 and a V2 one
// (corpus/f_module_v2.gsd, the F-Link's preset module, F_WD_Time 150 ms) at 6, our master polling
// every 10 ms on the manual clock. Each fault injected into the device's safety PDUs shows at the
// host as [IEC 61784-3-3 F-Host behaviour] says: a CRC2 fault or a consecutive-number fault
// passivates it at once, a stale or late answer when F_WD_Time passes without a valid new one,
// a wrong F_Dest_Add at start-up keeps the device without F-parameters (diagnosis 64) and the
// host passivated; after each, healthy answers raise ACK_REQ and ACK_REI reintegrates.
#include "dp/link/memory_bus.h"
#include "dp/master/master.h"
#include "gsd/interp.h"
#include "gsd/station/gsd_master_slaves.h"
#include "gsd/station/gsd_station.h"
#include "gsd/unit_diag.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

namespace rs4sim::gsd {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using profisafe::FHostState;
constexpr std::array<std::uint8_t, 2> kAddresses{5, 6};  // V1, V2

GsdStationSpec spec_of(const std::string& file, const std::vector<std::string>& modules,
                       std::uint8_t address) {
  auto d = parse(testing::corpus(file), file);
  EXPECT_TRUE(d) << (d ? "" : d.error().what());
  auto device = std::make_shared<const Device>(d.value());
  auto c = configure(*device, {modules, {}});
  EXPECT_TRUE(c) << (c ? "" : c.error().what());
  return station_spec(file, device, c.value(), address);
}

class FBus : public ::testing::Test {
 protected:
  void SetUp() override {
    std::vector<GsdStationSpec> specs;
    specs.push_back(spec_of("f_module_v1.gsd", {"PROFIsafe v1.x Module"}, 5));
    specs.push_back(spec_of("f_module_v2.gsd", {}, 6));
    dp::master::MasterConfig m;
    m.address = 1;
    for (const auto& s : specs) m.slaves.push_back(master_entry(s, 100ms).value());
    master_ = std::make_unique<dp::master::Master>(m);
    bus_.attach(*master_);
    hosts_ = std::make_unique<GsdMasterSlaves>(specs);
    for (auto& s : specs) {
      stations_.push_back(std::make_unique<GsdStation>(std::move(s)));
      bus_.attach(*stations_.back());
    }
    bus_.start();
    run(1s);
  }
  void run(dp::Duration d) {
    bus_.run_until([] { return false; }, clock_.now() + d, [this] {
      events_.clear();
      master_->take_events(events_);
      for (const auto& e : events_) {
        if (std::holds_alternative<dp::master::CycleCompleted>(e)) {
          (void)hosts_->on_master_cycle(*master_, clock_.now(), false);
        }
      }
    });
  }
  GsdStation& station(std::uint8_t a) { return *stations_[a - 5]; }
  FModuleDevice& device(std::uint8_t a) { return station(a).application().f_modules().at(0); }
  const profisafe::FHost& host(std::uint8_t a) { return hosts_->find(a)->f_module(0)->host; }
  // Healthy again: ACK_REQ, then ACK_REI brings the host back to run.
  void reintegrates(std::uint8_t a) {
    run(500ms);
    ASSERT_EQ(host(a).state(), FHostState::kAckRequired) << int{a};
    ASSERT_FALSE(hosts_->acknowledge(a, 0));
    run(100ms);
    EXPECT_EQ(host(a).state(), FHostState::kRun) << int{a};
  }

  dp::ManualClock clock_;
  dp::link::MemoryBus bus_{clock_};
  std::unique_ptr<dp::master::Master> master_;
  std::vector<std::unique_ptr<GsdStation>> stations_;
  std::unique_ptr<GsdMasterSlaves> hosts_;
  std::vector<dp::master::MasterEvent> events_;
};

TEST_F(FBus, BothReachRunAndCarryTheFDataBothWays) {
  for (const std::uint8_t a : kAddresses) {
    EXPECT_EQ(host(a).state(), FHostState::kRun) << int{a};
    EXPECT_EQ(f_state_token(device(a).device()), "run") << int{a};
    EXPECT_EQ(host(a).counters().passivations, 0U) << int{a};
  }
  EXPECT_EQ(f_mode_token(device(5).device()), "V1");
  EXPECT_EQ(f_mode_token(device(6).device()), "V2");
  const Bytes v1_in{0x11, 0x22, 0x33, 0x44}, v2_in{1, 2, 3, 4, 5, 6, 7, 8};
  ASSERT_FALSE(station(5).application().set_inputs(0, v1_in));
  ASSERT_FALSE(station(6).application().set_inputs(0, v2_in));
  ASSERT_FALSE(hosts_->set_f_outputs(5, 0, Bytes{0xA5, 0, 0, 0x5A}));
  run(50ms);
  EXPECT_EQ(Bytes(host(5).input().begin(), host(5).input().end()), v1_in);
  EXPECT_EQ(Bytes(host(6).input().begin(), host(6).input().end()), v2_in);
  EXPECT_EQ(Bytes(device(5).f_outputs().begin(), device(5).f_outputs().end()),
            (Bytes{0xA5, 0, 0, 0x5A}));
}

TEST_F(FBus, ACorruptCrc2PassivatesTheHostAtOnce) {
  for (const std::uint8_t a : kAddresses) {
    device(a).device().faults().corrupt_crc2 = 1;
    run(20ms);
    EXPECT_EQ(host(a).counters().crc_errors, 1U) << int{a};
    EXPECT_EQ(host(a).counters().passivations, 1U) << int{a};
    EXPECT_EQ(host(a).input()[0], 0) << int{a};  // the substitute value
    reintegrates(a);
  }
}

// V1 sends the number: the host sees a consecutive-number fault. V2 sends none, the virtual
// number is only inside CRC2: the same fault is a CRC2 fault at the host [IEC 61784-3-3 safety
// PDU].
TEST_F(FBus, AWrongConsecutiveNumberPassivatesTheHost) {
  device(5).device().faults().skip_number = 1;
  device(6).device().faults().skip_number = 1;
  run(20ms);
  EXPECT_EQ(host(5).counters().number_errors, 1U);
  EXPECT_EQ(host(5).counters().crc_errors, 0U);
  EXPECT_EQ(host(6).counters().crc_errors, 1U);
  for (const std::uint8_t a : kAddresses) {
    EXPECT_EQ(host(a).counters().passivations, 1U) << int{a};
    reintegrates(a);
  }
}

// A repeated (stale) answer is no fault in itself; answers stale for longer than F_WD_Time
// (V1 100 ms, one poll every 10 ms) are a timeout.
TEST_F(FBus, StaleAnswersPassivateOnlyAfterFWdTime) {
  device(5).device().faults().repeat_number = 5;
  run(200ms);
  EXPECT_GT(host(5).counters().stale, 0U);
  EXPECT_EQ(host(5).counters().passivations, 0U);
  EXPECT_EQ(host(5).state(), FHostState::kRun);
  device(5).device().faults().repeat_number = 15;
  run(200ms);
  EXPECT_EQ(host(5).counters().watchdog_timeouts, 1U);
  EXPECT_EQ(host(5).counters().passivations, 1U);
  reintegrates(5);
}

// Answers held back: 60 ms is within F_WD_Time (V2 150 ms), 200 ms is not.
TEST_F(FBus, ALateAnswerIsATimeoutOnlyBeyondFWdTime) {
  device(6).hold_answers(60ms);
  run(300ms);
  EXPECT_EQ(host(6).counters().passivations, 0U);
  EXPECT_EQ(host(6).state(), FHostState::kRun);
  device(6).hold_answers(200ms);
  run(300ms);
  EXPECT_EQ(host(6).counters().watchdog_timeouts, 1U);
  EXPECT_EQ(host(6).counters().passivations, 1U);
  reintegrates(6);
}

// The address switch at 2 and a power-up: our master's Set_Prm carries F_Dest_Add 1, refused
// with diagnosis 64 in the status block `05 81 00 00 40`; V1's GSD names it ("F add. does not
// match F_Dest_Add", its X_Value(64)), V2's has no text: the standard's meaning.
TEST_F(FBus, AWrongFDestAddAtStartUpIsDiagnosis64AndTheHostPassivates) {
  for (const std::uint8_t a : kAddresses) {
    ASSERT_FALSE(station(a).set_f_dest_add(0, 2));
    run(500ms);
    EXPECT_EQ(device(a).device().diagnosis(), 64) << int{a};
    EXPECT_EQ(f_state_token(device(a).device()), "parameter-fault") << int{a};
    EXPECT_EQ(Bytes(station(a).application().diagnosis_blocks().begin(),
                    station(a).application().diagnosis_blocks().end()),
              (Bytes{0x05, 0x81, 0x00, 0x00, 64}));
    EXPECT_NE(master_->poll_state(a), dp::master::PollState::kDataExchange);
    EXPECT_TRUE(host(a).passivated()) << int{a};
  }
  EXPECT_EQ(diagnosis_text(*station(5).spec().device, station(5).application().diagnosis_blocks()),
            "F add. does not match F_Dest_Add");
  EXPECT_EQ(diagnosis_text(*station(6).spec().device, station(6).application().diagnosis_blocks()),
            "Mismatch of safety destination address (F_Dest_Add)");
  EXPECT_NE(station(5).application().prm_fault().find("F add. does not match F_Dest_Add"),
            std::string::npos);
  EXPECT_TRUE(station(5).set_f_dest_add(1, 2));  // slot index 1: no F-module there
  for (const std::uint8_t a : kAddresses) {
    ASSERT_FALSE(station(a).set_f_dest_add(0, 1));
    reintegrates(a);
  }
}

}  // namespace
}  // namespace rs4sim::gsd
