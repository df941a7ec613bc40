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
  // 1.5M has no tested setting of its own: it keeps 500k's 8 ms (a PC answers no faster at a
  // faster rate) = 12 000 bit times, not the measured 2 ms + 11 bit times (3011), and is not
  // advised. (Before: 3011 bit times, 2.007 ms, less than the 8 ms asked at 500k.)
  EXPECT_TRUE(row(rows, dp::BaudRate::k1M5).floor);
  EXPECT_FALSE(row(rows, dp::BaudRate::k1M5).tested);
  EXPECT_EQ(row(rows, dp::BaudRate::k1M5).bits, 12000U);
  // 3M: 8 ms = 24 000 bit times, above TSL's 16383; 12M the same.
  EXPECT_EQ(row(rows, dp::BaudRate::k3M).bits, std::nullopt);
  EXPECT_EQ(row(rows, dp::BaudRate::k12M).bits, std::nullopt);
}

// From 93.75k on (one tested setting, 8 ms, up to 500k) a faster rate asks for less time than
// a slower one only by its shorter first character: a PC answers no faster when the bits get
// shorter. (19.2k's tested 30 ms is more than 93.75k's 8 ms: those are profirust's settings.)
// 3096 µs is the case seen: 1.5M asked 6.192 ms, 500k 8 ms.
TEST(SlotTimeTable, AFasterRateAsksForLessTimeOnlyByItsShorterCharacter) {
  for (const std::chrono::nanoseconds worst : {0ns, 1000000ns, 3096000ns, 5000000ns, 14000000ns}) {
    const auto rows = slot_time_table(worst);
    for (std::size_t i = 1; i < rows.size(); ++i) {
      const double slower_bps = dp::bits_per_second(rows[i - 1].rate);
      if (slower_bps < 93750) continue;
      EXPECT_GE(rows[i].ms + 11.0 * 1e3 / slower_bps, rows[i - 1].ms)
          << dp::to_string(rows[i].rate) << " after " << dp::to_string(rows[i - 1].rate);
    }
  }
  const auto seen = slot_time_table(3096us);
  EXPECT_DOUBLE_EQ(row(seen, dp::BaudRate::k1M5).ms, 8.0);
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

// The advice: the fastest rate with a tested setting (up to 500k) that the line can serve.
TEST(SlotTimeTable, TheRecommendedRateIsTheFastestTestedOneTheLineServes) {
  const auto fast = recommended_rate(slot_time_table(1ms));
  ASSERT_TRUE(fast.has_value());
  EXPECT_EQ(fast->rate, dp::BaudRate::k500k);  // 1.5M fits too, but is not advised
  EXPECT_EQ(fast->bits, 4000U);
  // 14 ms worst: 28 ms + a character; at 500k 14 000 + 11 bit times still fit.
  EXPECT_EQ(recommended_rate(slot_time_table(14ms))->rate, dp::BaudRate::k500k);
  // 20 ms worst: 40 ms; 500k would need 20 000 bit times, 187.5k 7500 + 11.
  const auto slow = recommended_rate(slot_time_table(20ms));
  ASSERT_TRUE(slow.has_value());
  EXPECT_EQ(slow->rate, dp::BaudRate::k187k5);
  EXPECT_EQ(slow->bits, 7511U);
  // 1 s worst: even 9.6k needs 2 s = 19 200 bit times.
  EXPECT_FALSE(recommended_rate(slot_time_table(1s)).has_value());
  std::ostringstream out;
  print_slot_time_table(out, slot_time_table(1ms));
  EXPECT_NE(out.str().find("recommended: 500k, TSL 4000 bit times (8.000 ms), retry limit 2-3"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("12000     8.000  not advised: nothing tested above 500k"),
            std::string::npos)
      << out.str();
}

TEST(SerialCheckAdvice, APtyGetsAdviceAboutItsOtherEndARealPortAboutTheWiring) {
  const std::string pty = nothing_answered_advice(true, "/dev/pts/7", "187.5k", 4);
  EXPECT_NE(pty.find("pseudo-terminal"), std::string::npos) << pty;
  EXPECT_NE(pty.find("rs4sim run --address 4 --link pty --baud 187.5k"), std::string::npos) << pty;
  EXPECT_EQ(pty.find("A/B"), std::string::npos) << pty;
  const std::string real = nothing_answered_advice(false, "/dev/ttyUSB0", "187.5k", 4);
  EXPECT_NE(real.find("check the wiring (A/B), the termination"), std::string::npos) << real;
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
