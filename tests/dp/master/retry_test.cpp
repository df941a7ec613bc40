// Slot time, retries with the same FCB and lost-slave detection (
// [IEC 61158-4-3 bus parameters, timing, FCB/FCV] [IEC 61158-6-3 slave supervision]), on the manual
// clock.

#include "master_fixture.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::master::testing {
namespace {

using std::chrono::microseconds;
using std::chrono::nanoseconds;

// Data_Exchange to slave 5 with output A5, FCV=1 FCB=0.
const Bytes kDx5D = {0x68,
                     0x04,
                     0x04,
                     0x68,  // SD2, LE 4
                     0x05,
                     0x02,  // DA 5, SA 2
                     0x5D,  // SRD high, FCV=1, FCB=0
                     0xA5,  // output
                     fcs({0x05, 0x02, 0x5D, 0xA5}),
                     0x16};
const Bytes kFdlStatus = {0x10, 0x05, 0x02, 0x49, 0x50, 0x16};

// 1.5 Mbit/s: TSL 300 bit = 200 µs; the 10-byte DX request and the longest accepted
// reply (10 bytes: SD2 with one input byte) take 110 bit = 73.3 µs each on the wire.
constexpr auto kTsl = microseconds(200);
constexpr auto kTenChars = nanoseconds(73'334);

TEST(MasterRetry, RetriesWithTheSameFcbAfterTheSlotTime) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_FALSE(f.master.set_outputs(5, Bytes{0xA5}));
  EXPECT_EQ(hex(f.step()), hex(kDx5D));
  const TimePoint sent = f.clock.now();
  f.clock.set(sent + kTsl);
  EXPECT_TRUE(f.poke().empty()) << "still inside the slot time";
  f.clock.set(sent + kTsl + 2 * kTenChars - nanoseconds(10));
  EXPECT_TRUE(f.poke().empty());
  f.clock.set(sent + kTsl + 2 * kTenChars + nanoseconds(10));
  EXPECT_EQ(hex(f.poke()), hex(kDx5D)) << "retry keeps FCB=0";
  f.reply({0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x44, fcs({0x02, 0x05, 0x08, 0x44}), 0x16});
  EXPECT_EQ(f.master.inputs(5)[0], 0x44);
  const auto st = f.master.slave_status(5);
  EXPECT_EQ(st->counters.retries, 1U);
  EXPECT_EQ(st->counters.no_answer, 0U);
  EXPECT_EQ(f.master.counters().slot_timeouts, 1U);
  // The next cycle's frame toggles FCB again: 7D.
  EXPECT_EQ(f.step()[6], 0x7D);
}

TEST(MasterRetry, LostSlaveAfterRetryLimitRestartsStartUp) {
  MasterFixture f;
  f.bring_to_dx();
  ASSERT_FALSE(f.master.set_outputs(5, Bytes{0xA5}));
  EXPECT_EQ(hex(f.step()), hex(kDx5D));
  EXPECT_EQ(hex(f.step()), hex(kDx5D));  // retry 1 (max_retry_limit = 1)
  EXPECT_TRUE(f.master.inputs(5).size() == 1);
  const Bytes next = f.step();  // gives up, next cycle: FDL_Status
  const auto left = f.events<SlaveLeftDataExchange>();
  ASSERT_EQ(left.size(), 1U);
  EXPECT_EQ(left[0].address, 5);
  EXPECT_EQ(left[0].reason, make_error_code(MasterError::kNoAnswer));
  EXPECT_EQ(hex(next), hex(kFdlStatus));
  EXPECT_TRUE(f.master.inputs(5).empty()) << "no inputs outside data exchange";
  f.reply({0x10, 0x02, 0x05, 0x00, 0x07, 0x16});
  // Fresh FCB after the slave was marked non-operational: first frame 6D ([IEC 61158-4-3 FCB/FCV]
  // [IEC 61158-6-3 slave supervision]).
  EXPECT_EQ(hex(f.step()), "68 05 05 68 85 82 6D 3C 3E EE 16");
  const auto st = f.master.slave_status(5);
  EXPECT_EQ(st->counters.no_answer, 1U);
  EXPECT_EQ(st->counters.left_data_exchange, 1U);
  EXPECT_EQ(st->last_error, make_error_code(MasterError::kNoAnswer));
}

TEST(MasterRetry, FirstFrameIsNotRetried) {
  MasterConfig cfg = example_master();
  cfg.fdl_status_first = false;
  MasterFixture f(cfg);
  const Bytes first = {0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x6D, 0x3C, 0x3E, 0xEE, 0x16};
  EXPECT_EQ(hex(f.step()), hex(first));
  const TimePoint sent = f.clock.now();
  EXPECT_EQ(hex(f.step()), hex(first));  // the next cycle's attempt, not a retry
  EXPECT_GE(f.clock.now() - sent, std::chrono::milliseconds(10));
  const auto st = f.master.slave_status(5);
  EXPECT_EQ(st->counters.retries, 0U);
  EXPECT_EQ(st->counters.no_answer, 1U);
  // The fault is reported once, not once per attempt.
  f.step();
  f.step();
  EXPECT_EQ(f.events<SlaveFault>().size(), 1U);
}

TEST(MasterRetry, GarbledReplyIsRetriedAfterTheSlotTime) {
  MasterFixture f;
  f.bring_to_dx();
  const Bytes dx = f.step();
  f.master.on_malformed_frame(make_error_code(fdl::DecodeError::kBadFcs));
  EXPECT_EQ(f.master.counters().malformed_frames, 1U);
  EXPECT_TRUE(f.poke().empty()) << "no immediate repeat";
  EXPECT_EQ(hex(f.step()), hex(dx)) << "same FCB after the slot time";
}

TEST(MasterRetry, RetryLimitIsConfigurable) {
  MasterConfig cfg = example_master();
  cfg.bus.max_retry_limit = 3;
  MasterFixture f(cfg);
  f.bring_to_dx();
  const Bytes dx = f.step();
  for (int i = 0; i < 3; ++i) EXPECT_EQ(hex(f.step()), hex(dx)) << "retry " << i + 1;
  f.step();
  EXPECT_EQ(f.master.slave_status(5)->counters.retries, 3U);
  EXPECT_EQ(f.master.slave_status(5)->counters.no_answer, 1U);
}

TEST(MasterRetry, ForeignAndLateTelegramsAreIgnored) {
  MasterFixture f;
  f.bring_to_dx();
  f.step();
  const auto deadline = f.master.next_deadline();
  // A reply from slave 6 and a request from another master do not complete the request.
  f.reply({0x68, 0x04, 0x04, 0x68, 0x02, 0x06, 0x08, 0x3C, fcs({0x02, 0x06, 0x08, 0x3C}), 0x16});
  f.reply({0x10, 0x05, 0x09, 0x49, fcs({0x05, 0x09, 0x49}), 0x16});
  EXPECT_EQ(f.master.next_deadline(), deadline);
  EXPECT_EQ(f.master.counters().ignored_telegrams, 2U);
  f.step();                                // retry
  f.clock.set(*f.master.next_deadline());  // slot time expires again: no answer
  EXPECT_TRUE(f.poke().empty());
  const auto ignored = f.master.counters().ignored_telegrams;
  f.reply({0xE5});  // too late: nothing outstanding
  EXPECT_EQ(f.master.counters().ignored_telegrams, ignored + 1);
}

}  // namespace
}  // namespace rs4sim::dp::master::testing
