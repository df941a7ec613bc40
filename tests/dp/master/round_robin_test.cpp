// Many slaves ([IEC 61158-6-3 class 1 master cycle]): 125 slaves started and polled round robin in
// configuration order, against a scripted responder that answers per DSAP as
// [IEC 61158-6-3 DP-V0 services] says.

#include "master_fixture.h"

#include <gtest/gtest.h>

#include <array>
#include <map>

namespace rs4sim::dp::master::testing {
namespace {

// Answers like a DP slave that accepts every parameterisation: FDL_Status → `00`,
// Slave_Diag → WAIT_PRM or ready, Set_Prm/Chk_Cfg → SC, Data_Exchange → DL with one
// input byte = own address.
class Responder {
 public:
  std::optional<fdl::Telegram> answer(const fdl::Telegram& req) {
    const std::uint8_t slave = req.da;
    const std::uint8_t master = req.sa;
    using S = fdl::ResponseStatus;
    if (req.fc.function() == fdl::RequestFunction::kFdlStatus) {
      return fdl::make_data_telegram(master, slave, fdl::FrameControl::response(S::kOk),
                                     std::nullopt, std::nullopt, {});
    }
    if (!req.dsap) {
      const std::uint8_t in[] = {slave};
      return fdl::make_data_telegram(master, slave, fdl::FrameControl::response(S::kDataLow),
                                     std::nullopt, std::nullopt, in);
    }
    switch (*req.dsap) {
      case 60: {
        const bool ready = parameterised_[slave];
        const std::uint8_t du[] = {static_cast<std::uint8_t>(ready ? 0x00 : 0x02),
                                   static_cast<std::uint8_t>(ready ? 0x0C : 0x05),
                                   0x00,
                                   static_cast<std::uint8_t>(ready ? master : 0xFF),
                                   0x12,
                                   0x34};
        return fdl::make_data_telegram(master, slave, fdl::FrameControl::response(S::kDataLow),
                                       *req.ssap, *req.dsap, du);
      }
      case 61: parameterised_[slave] = true; return fdl::make_short_ack();
      case 62: return fdl::make_short_ack();
      default: return std::nullopt;
    }
  }

 private:
  std::array<bool, 128> parameterised_{};
};

TEST(MasterRoundRobin, HundredTwentyFiveSlaves) {
  MasterConfig cfg = example_master();
  cfg.address = 0;
  cfg.slaves.clear();
  for (std::uint8_t a = 1; a <= 125; ++a) cfg.slaves.push_back(example_slave(a));
  MasterFixture f(cfg);
  Responder responder;
  // Data_Exchange destinations per cycle (index = cycles completed before it was sent).
  std::map<std::uint64_t, std::vector<std::uint8_t>> dx_by_cycle;
  std::optional<std::uint64_t> first_full;  // first cycle that ended with all 125 in DX
  for (int i = 0; i < 200'000 && !(first_full && f.master.counters().cycles > *first_full + 5);
       ++i) {
    if (auto d = f.master.next_deadline(); d && *d > f.clock.now()) f.clock.set(*d);
    f.master.on_time(f.clock.now());
    while (auto t = f.master.take_transmit()) {
      if (!t->dsap && t->fc.function() == fdl::RequestFunction::kSrdHigh) {
        dx_by_cycle[f.master.counters().cycles].push_back(t->da);
      }
      f.clock.advance(std::chrono::microseconds(30));
      if (auto r = responder.answer(*t)) f.master.on_telegram(*r, f.clock.now());
    }
    for (const auto& c : f.events<CycleCompleted>()) {
      if (c.slaves_in_data_exchange == 125 && !first_full) first_full = c.cycle;
    }
  }
  ASSERT_TRUE(first_full);
  for (std::uint64_t c = *first_full; c < *first_full + 5; ++c) {
    const auto& order = dx_by_cycle[c];
    ASSERT_EQ(order.size(), 125U) << "cycle " << c;
    for (std::size_t i = 0; i < order.size(); ++i) ASSERT_EQ(order[i], i + 1) << "cycle " << c;
  }
  for (std::uint8_t a = 1; a <= 125; ++a) {
    ASSERT_EQ(f.master.inputs(a).size(), 1U);
    EXPECT_EQ(f.master.inputs(a)[0], a);
    const auto st = f.master.slave_status(a);
    EXPECT_EQ(st->counters.entered_data_exchange, 1U);
    EXPECT_EQ(st->counters.no_answer, 0U);
  }
  EXPECT_EQ(f.events<SlaveEnteredDataExchange>().size(), 125U);
  EXPECT_EQ(f.master.slave_addresses().size(), 125U);
}

}  // namespace
}  // namespace rs4sim::dp::master::testing
