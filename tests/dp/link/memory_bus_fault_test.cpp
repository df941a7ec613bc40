// MemoryBus wire model ([IEC 61158-4-3 UART character] [IEC 61158-2 baud rates] 11 bit/char,
// [IEC 61158-4-3 bus parameters, timing] TSYN/TSDR) and fault injection.
#include "dp/link/memory_bus.h"
#include "tests/dp/link/fake_station.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::link {
namespace {

using namespace std::chrono_literals;
using namespace testing;  // FakeStation, srd_request
using Bytes = std::vector<std::uint8_t>;

TEST(MemoryBusWire, ArrivalIsTsynPlusElevenBitsPerCharacterAtTwelveMegabit) {
  ManualClock clock;
  MemoryBus bus(clock, {BaudRate::k12M, kMinTsdrBits});
  FakeStation master(2), slave(5, FakeStation::Reply::kEchoData);
  bus.attach(master);
  bus.attach(slave);
  const TimePoint t0 = clock.now();
  master.outbox.push_back(srd_request(5, 2, {0xA5}));  // 10 bytes on the wire
  bus.start();
  while (bus.step()) {
  }
  ASSERT_EQ(slave.received.size(), 1U);
  // Request: TSYN 33 bit + 10 chars · 11 bit = 143 bit; 143 / 12e6 s = 11916.67 ns → 11917.
  EXPECT_EQ(slave.received[0].at - t0, 11917ns);
  // Reply (10 bytes) starts min TSDR 11 bit after the request ended: 11 + 110 = 121 bit
  // = 10083.33 ns → 10084 (each telegram is rounded up to whole ns once).
  ASSERT_EQ(master.received.size(), 1U);
  EXPECT_EQ(master.received[0].at - t0, 11917ns + 10084ns);
}

TEST(MemoryBusWire, SlowRateAndTheLineCarriesOneTelegramAtATime) {
  ManualClock clock;
  MemoryBus bus(clock, {BaudRate::k9k6, kMinTsdrBits});
  FakeStation a(1), b(2), c(3);
  bus.attach(a);
  bus.attach(b);
  bus.attach(c);
  const TimePoint t0 = clock.now();
  // SD1 FDL_Status requests, 6 bytes each ([IEC 61158-4-3 frame formats]): 33 + 66 = 99 bit
  // = 10.3125 ms at 9.6k.
  const auto status = [](std::uint8_t da, std::uint8_t sa) {
    return fdl::make_data_telegram(
        da, sa, fdl::FrameControl::request(fdl::RequestFunction::kFdlStatus, false, false),
        std::nullopt, std::nullopt, {});
  };
  a.outbox.push_back(status(2, 1));
  a.outbox.push_back(status(3, 1));
  bus.start();
  while (bus.step()) {
  }
  ASSERT_EQ(b.received.size(), 1U);
  ASSERT_EQ(c.received.size(), 1U);
  EXPECT_EQ(b.received[0].at - t0, 10'312'500ns);
  EXPECT_EQ(c.received[0].at - t0, 2 * 10'312'500ns);  // waits for the line
}

TEST(MemoryBusWire, ATelegramStartsAtItsSendTimeAndNotBefore) {
  ManualClock clock;
  MemoryBus bus(clock, {BaudRate::k12M, kMinTsdrBits});
  FakeStation master(2), slave(5);
  bus.attach(master);
  bus.attach(slave);
  std::vector<TimePoint> started;
  bus.add_observer([&](const BusEvent& e) { started.push_back(e.time); });
  const TimePoint t0 = clock.now();
  master.hold = t0 + 5us;  // e.g. a request handed out with the reply, due TID1 later
  master.outbox.push_back(srd_request(5, 2, {0xA5}));  // 10 bytes: 143 bit = 11917 ns
  bus.start();
  ASSERT_EQ(started.size(), 1U);
  EXPECT_EQ(started[0], t0 + 5us);  // handed out at t0, on the line at its send time
  bus.run_until(t0 + 5us + 11916ns);
  EXPECT_TRUE(slave.received.empty());
  bus.run_until(t0 + 5us + 11917ns);
  ASSERT_EQ(slave.received.size(), 1U);
  EXPECT_EQ(slave.received[0].at, t0 + 5us + 11917ns);
}

TEST(MemoryBusWire, ASendTimeAlreadyPassedMeansAtOnce) {
  ManualClock clock;
  MemoryBus bus(clock, {BaudRate::k12M, kMinTsdrBits});
  FakeStation master(2), slave(5);
  bus.attach(master);
  bus.attach(slave);
  const TimePoint t0 = clock.now();
  master.hold = t0;
  clock.set(t0 + 1ms);
  master.outbox.push_back(srd_request(5, 2, {0xA5}));
  bus.start();
  while (bus.step()) {
  }
  ASSERT_EQ(slave.received.size(), 1U);
  EXPECT_EQ(slave.received[0].at, t0 + 1ms + 11917ns);
}

TEST(MemoryBusWire, WithoutTheWireModelATelegramArrivesAtItsSendTime) {
  ManualClock clock;
  MemoryBus bus(clock);
  FakeStation master(2), slave(5);
  bus.attach(master);
  bus.attach(slave);
  const TimePoint t0 = clock.now();
  master.hold = t0 + 24'667ns;
  master.outbox.push_back(srd_request(5, 2, {0xA5}));
  bus.start();
  bus.run_until(t0 + 24'666ns);
  EXPECT_TRUE(slave.received.empty());
  while (bus.step()) {
  }
  ASSERT_EQ(slave.received.size(), 1U);
  EXPECT_EQ(slave.received[0].at, t0 + 24'667ns);
}

class MemoryBusFaults : public ::testing::Test {
 protected:
  void SetUp() override {
    bus.attach(master);
    bus.attach(slave);
    bus.start();
  }
  void exchange(Bytes out) {
    master.send(srd_request(5, 2, std::move(out)));
    bus.run_for(1ms);
  }
  ManualClock clock;
  MemoryBus bus{clock};
  FakeStation master{2}, slave{5, FakeStation::Reply::kEchoData};
};

TEST_F(MemoryBusFaults, DropLosesExactlyTheNextMatchingTelegram) {
  bus.inject({FaultKind::kDrop, 2, 5, 1});
  exchange({0x11});
  EXPECT_TRUE(slave.received.empty());
  EXPECT_EQ(bus.counters(2).dropped, 1U);
  exchange({0x22});
  ASSERT_EQ(slave.received.size(), 1U);
  EXPECT_EQ(slave.received[0].telegram.data[0], 0x22);
  ASSERT_EQ(master.received.size(), 1U);
}

TEST_F(MemoryBusFaults, DropOfTheReplyOnly) {
  bus.inject({FaultKind::kDrop, 5, std::nullopt, 1});
  exchange({0x11});
  EXPECT_EQ(slave.received.size(), 1U);
  EXPECT_TRUE(master.received.empty());
  EXPECT_EQ(bus.counters(5).dropped, 1U);
}

TEST_F(MemoryBusFaults, EverySingleBitFlipOfADataExchangeIsRejectedByTheReceiver) {
  // 10-byte frame = 80 bits; FCS ([IEC 61158-4-3 FCS]), LE/LEr, SD and ED checks must catch each
  // flip.
  for (std::uint32_t bit = 0; bit < 80; ++bit) {
    bus.inject({FaultKind::kCorrupt, 2, 5, 1, {}, bit});
    exchange({0x5A});
    bus.run_for(1ms);
  }
  EXPECT_TRUE(slave.received.empty());
  EXPECT_EQ(bus.counters(2).corrupted, 80U);
  EXPECT_GE(bus.counters(5).malformed, 80U);
  EXPECT_GE(bus.decoder_stats(5).total_errors(), 80U);
  EXPECT_TRUE(master.received.empty());
}

TEST_F(MemoryBusFaults, CorruptedShortAckIsNotTakenAsAnAck) {
  FakeStation acker(7, FakeStation::Reply::kShortAck);
  bus.attach(acker);
  bus.inject({FaultKind::kCorrupt, 7, 2, 1, {}, 3});  // E5 → ED
  master.send(srd_request(7, 2, {0x01}));
  bus.run_for(1ms);
  EXPECT_EQ(acker.received.size(), 1U);
  EXPECT_TRUE(master.received.empty());
  EXPECT_EQ(bus.counters(2).malformed, 1U);
}

TEST_F(MemoryBusFaults, DelayShiftsTheArrival) {
  bus.inject({FaultKind::kDelay, 2, 5, 1, 7ms});
  const TimePoint t0 = clock.now();
  exchange({0x01});
  EXPECT_TRUE(slave.received.empty());  // still on its way after 1 ms
  bus.run_for(10ms);
  ASSERT_EQ(slave.received.size(), 1U);
  EXPECT_EQ(slave.received[0].at - t0, 7ms);
  EXPECT_EQ(bus.counters(2).delayed, 1U);
}

TEST_F(MemoryBusFaults, PermanentFaultUntilCleared) {
  const FaultId id = bus.inject({FaultKind::kDrop, 2, 5, 0});
  for (int i = 0; i < 5; ++i) exchange({0x01});
  EXPECT_TRUE(slave.received.empty());
  EXPECT_EQ(bus.counters(2).dropped, 5U);
  bus.clear_fault(id);
  exchange({0x02});
  EXPECT_EQ(slave.received.size(), 1U);
}

TEST_F(MemoryBusFaults, SilencedStationNeitherHearsNorSpeaks) {
  bus.set_silenced(5, true);
  exchange({0x01});
  EXPECT_TRUE(slave.received.empty());
  EXPECT_EQ(bus.counters(5).silenced, 1U);
  bus.set_silenced(5, false);
  bus.set_silenced(2, true);
  exchange({0x02});
  EXPECT_TRUE(slave.received.empty());
  EXPECT_EQ(bus.counters(2).silenced, 1U);
  bus.set_silenced(2, false);
  exchange({0x03});
  ASSERT_EQ(slave.received.size(), 1U);
  EXPECT_EQ(master.received.size(), 1U);
}

// Without faults a frame reaches the receiver as its telegram (Decoder::feed_encoded), but the
// receiver checks that encode() does not make still reject what the bytes would fail
// ([IEC 61158-4-3 frame reception]: an undefined FC code).
TEST_F(MemoryBusFaults, WithoutFaultsTheReceiverStillRejectsWhatTheBytesWouldFail) {
  fdl::Telegram bad_fc = srd_request(5, 2, {0x01});
  bad_fc.fc = fdl::FrameControl{0x41};  // request code 1 is undefined
  master.send(bad_fc);
  bus.run_for(1ms);
  EXPECT_TRUE(slave.received.empty());
  EXPECT_EQ(bus.counters(5).malformed, 1U);
  EXPECT_EQ(bus.decoder_stats(5).count(fdl::DecodeError::kBadFrameControl), 1U);
  exchange({0x02});  // the bus and the receiver carry on
  ASSERT_EQ(slave.received.size(), 1U);
  EXPECT_EQ(slave.received[0].telegram.data[0], 0x02);
  EXPECT_EQ(bus.decoder_stats(5).telegrams, 1U);
  EXPECT_EQ(master.received.size(), 1U);
}

// While any fault is injected, every frame travels as bytes through the receiver's full
// checks, also those the fault does not match; the outcome is the same as without faults.
TEST_F(MemoryBusFaults, AnUnmatchedFaultChangesNothingForOtherFrames) {
  bus.inject({FaultKind::kCorrupt, 9, 9, 0});  // permanent, matches no frame here
  exchange({0x33});
  ASSERT_EQ(slave.received.size(), 1U);
  EXPECT_EQ(slave.received[0].telegram.data[0], 0x33);
  ASSERT_EQ(master.received.size(), 1U);
  EXPECT_EQ(bus.decoder_stats(5).bytes, 10U);
  EXPECT_EQ(bus.decoder_stats(2).bytes, 10U);
  EXPECT_EQ(bus.decoder_stats(5).total_errors(), 0U);
}

}  // namespace
}  // namespace rs4sim::dp::link
