// Configuration checks, bus-parameter defaults ([IEC 61158-4-3 bus parameters, timing]), watchdog
// factors ([IEC 61158-6-3 Set_Prm]) and the error categories.

#include "master_fixture.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::master::testing {
namespace {

TEST(MasterConfigTest, BusParameterDefaultsFollowTheTable) {
  struct Row {
    BaudRate baud;
    std::uint32_t tsl, max_tsdr, tset, tqui;
  };
  // [IEC 61158-4-3 bus parameters, timing] default bus parameters (Tbit).
  const Row rows[] = {{BaudRate::k9k6, 100, 60, 1, 0},   {BaudRate::k187k5, 100, 60, 1, 0},
                      {BaudRate::k500k, 200, 100, 1, 0}, {BaudRate::k1M5, 300, 150, 1, 0},
                      {BaudRate::k3M, 400, 250, 4, 3},   {BaudRate::k6M, 600, 450, 8, 6},
                      {BaudRate::k12M, 1000, 800, 16, 9}};
  for (const Row& r : rows) {
    const BusParameters p = BusParameters::defaults_for(r.baud);
    EXPECT_EQ(p.tsl, r.tsl);
    EXPECT_EQ(p.max_tsdr, r.max_tsdr);
    EXPECT_EQ(p.tset, r.tset);
    EXPECT_EQ(p.tqui, r.tqui);
    EXPECT_EQ(p.min_tsdr, 11U);
    EXPECT_FALSE(validate(p)) << static_cast<std::uint32_t>(r.baud);
  }
}

TEST(MasterConfigTest, BitTimes) {
  const BusParameters slow = BusParameters::defaults_for(BaudRate::k9k6);
  EXPECT_EQ(slow.bits(1), std::chrono::nanoseconds(104'167));  // 104.2 µs
                                                               // ([IEC 61158-4-3 UART character]
                                                               // [IEC 61158-2 baud rates])
  const BusParameters fast = BusParameters::defaults_for(BaudRate::k12M);
  EXPECT_EQ(fast.bits(12), std::chrono::nanoseconds(1'000));
  EXPECT_EQ(fast.characters(1), std::chrono::nanoseconds(917));  // 11 bit, rounded up
  // TTO = TSL·(6 + 2·TS): 1000·(6 + 2·3) bit at 12 Mbit/s = 1 ms.
  EXPECT_EQ(fast.token_lost_timeout(3), std::chrono::milliseconds(1));
}

TEST(MasterConfigTest, BusParameterConstraints) {
  BusParameters p = BusParameters::defaults_for(BaudRate::k1M5);
  p.tsl = p.max_tsdr + 14;  // maxTSDR + 15 ≤ TSL violated
  EXPECT_EQ(validate(p), make_error_code(MasterError::kBadBusParameters));
  p = BusParameters::defaults_for(BaudRate::k1M5);
  p.min_tsdr = 10;
  EXPECT_EQ(validate(p), make_error_code(MasterError::kBadBusParameters));
  p = BusParameters::defaults_for(BaudRate::k1M5);
  p.tid1 = 32;  // below TSYN
  EXPECT_EQ(validate(p), make_error_code(MasterError::kBadBusParameters));
  p = BusParameters::defaults_for(BaudRate::k1M5);
  p.baud = static_cast<BaudRate>(1234);
  EXPECT_EQ(validate(p), make_error_code(MasterError::kBadBusParameters));
}

TEST(MasterConfigTest, SlaveAndMasterChecks) {
  EXPECT_FALSE(validate(example_master()));
  MasterConfig m = example_master();
  m.address = 127;
  EXPECT_EQ(validate(m), make_error_code(MasterError::kBadMasterAddress));
  m = example_master();
  m.slaves.push_back(example_slave(5));
  EXPECT_EQ(validate(m), make_error_code(MasterError::kDuplicateSlave));
  m = example_master();
  m.slaves[0].address = 2;  // the master's own address
  EXPECT_EQ(validate(m), make_error_code(MasterError::kDuplicateSlave));
  SlaveEntry s = example_slave();
  s.address = 126;  // default address is not for operation ([IEC 61158-4-3 addresses, SAPs])
  EXPECT_EQ(validate(s), make_error_code(MasterError::kBadSlaveConfig));
  s = example_slave();
  s.input_length = 2;  // Chk_Cfg says 1 byte in
  EXPECT_EQ(validate(s), make_error_code(MasterError::kBadSlaveConfig));
  s = example_slave();
  s.cfg.clear();  // Chk_Cfg needs 1..244 bytes
  EXPECT_EQ(validate(s), make_error_code(MasterError::kBadSlaveConfig));
  s = example_slave();
  s.c1_response_timeout = Duration::zero();
  EXPECT_EQ(validate(s), make_error_code(MasterError::kBadSlaveConfig));
  m = example_master();
  m.slaves[0].input_length = 3;
  EXPECT_THROW(Master{m}, std::system_error);
}

TEST(MasterConfigTest, WatchdogFactors) {
  // [IEC 61158-6-3 Set_Prm]: T_WD = 10 ms · F1 · F2.
  auto w = watchdog_factors(std::chrono::milliseconds(100));
  EXPECT_EQ(w.f1 * w.f2, 10);
  w = watchdog_factors(std::chrono::milliseconds(5000));
  EXPECT_EQ(w.f1 * w.f2, 500);
  EXPECT_LE(w.f2, 255);
  w = watchdog_factors(std::chrono::milliseconds(105));  // rounds up to 110 ms
  EXPECT_EQ(w.f1 * w.f2, 11);
  w = watchdog_factors(std::chrono::milliseconds(3'000'000));  // clamps to 650.25 s
  EXPECT_EQ(w.f1, 255);
  EXPECT_EQ(w.f2, 255);
  w = watchdog_factors(std::chrono::milliseconds(7), true);  // WD_Base_1ms
  EXPECT_EQ(w.f1 * w.f2, 7);
}

TEST(MasterConfigTest, ErrorCategories) {
  EXPECT_STREQ(error_category().name(), "dp.master");
  EXPECT_EQ(make_error_code(MasterError::kNoAnswer).message(),
            "slave does not answer (slot time expired after all retries)");
  for (int v = 1; v <= static_cast<int>(MasterError::kDuplicateSlave); ++v) {
    EXPECT_NE(error_category().message(v), "unknown master error") << v;
  }
  EXPECT_EQ(std::error_code(0xB5, dpv1_error_category()).message(),
            "DPV1 access error: state conflict");
  EXPECT_EQ(std::error_code(0xC2, dpv1_error_category()).message(),
            "DPV1 resource error: resource busy");
  EXPECT_EQ(std::error_code(0xAA, dpv1_error_category()).message(),
            "DPV1 application error: user specific or reserved code");
  EXPECT_EQ(
      to_error_code(pdu::Dpv1Error{pdu::Dpv1Function::kRead, 0x80, pdu::ErrorCode1::kNone, 0x00}),
      make_error_code(MasterError::kDpv1Negative));
}

TEST(MasterConfigTest, ObserverDispatch) {
  struct Counting : MasterObserver {
    int entered = 0, cycles = 0;
    void on_entered_data_exchange(const SlaveEnteredDataExchange&) override { ++entered; }
    void on_cycle(const CycleCompleted&) override { ++cycles; }
  } obs;
  dispatch(SlaveEnteredDataExchange{5}, obs);
  dispatch(CycleCompleted{1, 1}, obs);
  dispatch(DiagReceived{}, obs);
  EXPECT_EQ(obs.entered, 1);
  EXPECT_EQ(obs.cycles, 1);
}

}  // namespace
}  // namespace rs4sim::dp::master::testing
