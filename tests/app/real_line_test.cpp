// The real-line pieces of the runtime (docs/serial.md): the slot-time table of `rs4sim
// serial-check`, the --rt-priority refusal's text, the turnaround summary line.
#include "app/runtime/real_line.h"

#include "app/runtime/serial_check.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <sstream>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;

const SlotTimeRow& row(const std::vector<SlotTimeRow>& rows, dp::BaudRate r) {
  for (const auto& x : rows) {
    if (x.rate == r) return x;
  }
  throw std::out_of_range("rate");
}

TEST(SlotTimeTable, AFastLineGetsProfirustsTestedSettingsAsTheFloor) {
  const auto rows = slot_time_table(1ms);  // 2 ms + one character, below every floor
  ASSERT_EQ(rows.size(), 10U);
  EXPECT_TRUE(row(rows, dp::BaudRate::k19k2).floor);
  EXPECT_EQ(row(rows, dp::BaudRate::k19k2).bits, 576U);    // 30 ms x 19 200 bit/s
  EXPECT_EQ(row(rows, dp::BaudRate::k187k5).bits, 1500U);  // 8 ms x 187 500 bit/s
  EXPECT_EQ(row(rows, dp::BaudRate::k500k).bits, 4000U);   // 8 ms x 500 000 bit/s
  // 1.5M has no tested setting: 2 ms + 11 bit times = 3000 + 11 bit times.
  EXPECT_FALSE(row(rows, dp::BaudRate::k1M5).floor);
  EXPECT_EQ(row(rows, dp::BaudRate::k1M5).bits, 3011U);
  // 12M: 2 ms = 24 000 bit times, above TSL's 16383.
  EXPECT_EQ(row(rows, dp::BaudRate::k12M).bits, std::nullopt);
}

TEST(SlotTimeTable, ASlowLineIsDecidedByTheMeasurementAndTheBitLimit) {
  // 5 ms worst: 10 ms + a character at 187.5k = 1875 + 11 bit times, above the 8 ms floor.
  const auto rows = slot_time_table(5ms);
  EXPECT_FALSE(row(rows, dp::BaudRate::k187k5).floor);
  EXPECT_EQ(row(rows, dp::BaudRate::k187k5).bits, 1886U);
  // At 1.5M: 15 000 + 11 bit times still fit; 3M needs 30 011: not usable.
  EXPECT_EQ(row(rows, dp::BaudRate::k1M5).bits, 15011U);
  EXPECT_EQ(row(rows, dp::BaudRate::k3M).bits, std::nullopt);
  EXPECT_TRUE(row(rows, dp::BaudRate::k19k2).floor);  // 10 ms < 30 ms
}

TEST(RealtimeError, EpermNamesTheCapabilityAndTheLimit) {
  const std::string e = realtime_error("sched_setscheduler(SCHED_FIFO)", 50, EPERM);
  EXPECT_NE(e.find("--rt-priority 50"), std::string::npos) << e;
  EXPECT_NE(e.find("EPERM"), std::string::npos) << e;
  EXPECT_NE(e.find("CAP_SYS_NICE"), std::string::npos) << e;
  EXPECT_NE(e.find("ulimit -r 50"), std::string::npos) << e;
  const std::string m = realtime_error("mlockall", 50, ENOMEM);
  EXPECT_NE(m.find("ENOMEM"), std::string::npos) << m;
  EXPECT_NE(m.find("ulimit -l"), std::string::npos) << m;
}

TEST(TurnaroundSummary, TextAndJsonCarryTheSameFigures) {
  dp::link::TurnaroundStats s;
  s.record(100us);
  s.record(2ms);
  s.record_late();
  std::ostringstream text, json;
  print_turnaround(text, 5, s, 8000, false);
  print_turnaround(json, 5, s, 8000, true);
  // 100 µs: bucket 98 304..114 687 ns; the p50 is its bound; p99 the max (2 ms).
  EXPECT_EQ(text.str(),
            "turnaround 5: 2 replies, p50 0.115 ms, p99 2.000 ms, max 2.000 ms, mean 1.050 ms; "
            "late (> TSL 8.000 ms, not sent) 1\n"
            "  histogram (µs): < 114.688: 1, < 2097.152: 1\n");
  EXPECT_EQ(json.str(),
            R"({"event":"turnaround","address":5,"replies":2,"late":1,"tsl_us":8000,)"
            R"("p50_us":114.688,"p99_us":2000.000,"max_us":2000.000,"mean_us":1050.000,)"
            R"("histogram":[{"le_us":114.688,"count":1},{"le_us":2097.152,"count":1}]})"
            "\n");
}

TEST(TurnaroundSummary, TheTextHistogramNamesTheLastBucketByItsLowerBoundAndIsOmittedWhenEmpty) {
  dp::link::TurnaroundStats s;
  std::ostringstream none;
  print_turnaround(none, 4, s, std::nullopt, false);
  EXPECT_EQ(none.str(), "turnaround 4: 0 replies\n");  // no histogram line without replies
  s.record(500ns);                                     // below 1.024 µs: the first bucket
  s.record(500ns);
  s.record(40s);  // at or above 2^35 ns: the last bucket, unbounded
  std::ostringstream text;
  print_turnaround(text, 4, s, std::nullopt, false);
  EXPECT_EQ(text.str(),
            "turnaround 4: 3 replies, p50 0.001 ms, p99 40000.000 ms, max 40000.000 ms, "
            "mean 13333.334 ms\n"
            "  histogram (µs): < 1.024: 2, >= 34359738.368: 1\n");
}

}  // namespace
}  // namespace rs4sim::app
