// Global_Control broadcasts and the CLEAR operating mode
// ([IEC 61158-6-3 Global_Control, Data_Exchange, class 1 master cycle]).

#include "master_fixture.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::master::testing {
namespace {

const Bytes kDxDl = {0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x3C, 0x4B, 0x16};

TEST(MasterGlobalControl, ClearModeBroadcastsGcClearAndZeroOutputs) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_FALSE(f.master.set_outputs(5, Bytes{0xA5}));
  f.master.set_operating_mode(OperatingMode::kClear);
  // [docs/references.md#dp-worked-example] GC Clear of master 2.
  EXPECT_EQ(hex(f.step()), hex(Bytes{0x68, 0x07, 0x07, 0x68,  // SD2, LE 7
                                     0xFF,                    // DA 127 | extension
                                     0x82,                    // SA 2 | extension
                                     0x46,                    // SDN high, FCV=0 FCB=0
                                     0x3A, 0x3E,              // DSAP 58, SSAP 62
                                     0x02,                    // Control_Command: Clear_Data
                                     0x00,                    // Group_Select: all
                                     0x41, 0x16}));
  const TimePoint gc_sent = f.clock.now();
  // No reply to SDN: the next request waits the GC's 13 characters + TID2 (150 bit)
  // = 293 bit = 195.3 µs at 1.5 Mbit/s.
  f.clock.set(gc_sent + std::chrono::nanoseconds(195'300));
  EXPECT_TRUE(f.poke().empty());
  f.clock.set(gc_sent + std::chrono::nanoseconds(195'400));
  EXPECT_EQ(hex(f.poke()), hex(Bytes{0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x5D,
                                     0x00,  // outputs as zeros in CLEAR
                                     fcs({0x05, 0x02, 0x5D, 0x00}), 0x16}));
  f.reply(kDxDl);
  f.master.set_operating_mode(OperatingMode::kOperate);
  EXPECT_EQ(hex(f.step()), "68 07 07 68 FF 82 46 3A 3E 00 00 3F 16");  // GC Operate
  EXPECT_EQ(f.step()[7], 0xA5) << "outputs as set again";
  EXPECT_EQ(f.master.counters().global_controls, 2U);
}

TEST(MasterGlobalControl, FailSafeSlaveGetsEmptyDataExchangeInClear) {
  MasterConfig cfg = example_master();
  cfg.slaves[0].prm.dpv1->fail_safe = true;  // DPV1_Status_1 bit 6
  MasterFixture f(cfg);
  f.bring_to_dx();
  f.master.set_operating_mode(OperatingMode::kClear);
  f.step();                                 // GC Clear
  EXPECT_EQ(hex(f.step()), hex(Bytes{0x10,  // SD1: no data unit
                                     0x05, 0x02, 0x5D, fcs({0x05, 0x02, 0x5D}), 0x16}));
}

TEST(MasterGlobalControl, SyncFreezeWithGroups) {
  MasterFixture f;
  f.bring_to_dx();
  pdu::GlobalControl sync;
  sync.sync = true;
  sync.group_select = 0x02;  // group 2
  pdu::GlobalControl freeze;
  freeze.freeze = true;
  ASSERT_FALSE(f.master.global_control(sync));
  ASSERT_FALSE(f.master.global_control(freeze));
  EXPECT_EQ(hex(f.step()), hex(Bytes{0x68, 0x07, 0x07, 0x68, 0xFF, 0x82, 0x46, 0x3A, 0x3E,
                                     0x20,  // Sync (bit 5)
                                     0x02,  // Group_Select
                                     fcs({0xFF, 0x82, 0x46, 0x3A, 0x3E, 0x20, 0x02}), 0x16}));
  EXPECT_EQ(hex(f.step()), hex(Bytes{0x68, 0x07, 0x07, 0x68, 0xFF, 0x82, 0x46, 0x3A, 0x3E,
                                     0x08,  // Freeze (bit 3)
                                     0x00, fcs({0xFF, 0x82, 0x46, 0x3A, 0x3E, 0x08, 0x00}), 0x16}));
  EXPECT_EQ(f.step()[4], 0x05) << "then the slaves' turns";
}

TEST(MasterGlobalControl, RejectsReservedBitsAndOverflow) {
  MasterFixture f;
  pdu::GlobalControl bad;
  bad.reserved = 0x01;  // bit 0 reserved
  EXPECT_EQ(f.master.global_control(bad), make_error_code(MasterError::kBadArgument));
  pdu::GlobalControl ok;
  for (int i = 0; i < 8; ++i) ASSERT_FALSE(f.master.global_control(ok));
  EXPECT_EQ(f.master.global_control(ok), make_error_code(MasterError::kQueueFull));
}

TEST(MasterGlobalControl, PeriodicOperateBroadcast) {
  MasterConfig cfg = example_master();
  cfg.global_control_interval = std::chrono::milliseconds(20);
  MasterFixture f(cfg);
  const TimePoint t0 = f.clock.now();
  EXPECT_EQ(hex(f.step()), "68 07 07 68 FF 82 46 3A 3E 00 00 3F 16");
  EXPECT_EQ(hex(f.step()), "10 05 02 49 50 16");
  int gcs = 1;
  while (f.clock.now() - t0 < std::chrono::milliseconds(45)) {
    if (f.step()[4] == 0xFF) ++gcs;  // unanswered FDL_Status: the slave is absent
  }
  EXPECT_EQ(gcs, 3);  // at 0, 20 and 40 ms
}

}  // namespace
}  // namespace rs4sim::dp::master::testing
