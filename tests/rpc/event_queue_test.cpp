// The event stream's parts without gRPC: the bounded queue (what a slow client sees) and the
// telegram tap of real-time links. Known answers: the sequence numbering of docs/rpc.md
// "Event stream" and an FDL_Status request in SD1 [IEC 61158-4-3 frame formats].
#include "rpc/event_queue.h"

#include "rpc/event_hub.h"
#include "rpc/tapped_station.h"
#include "rs4/device/rs4_device.h"

#include <gtest/gtest.h>

namespace rs4sim::rpc {
namespace {

using namespace std::chrono_literals;

v1::Event state_event(const char* to) {
  v1::Event e;
  e.set_address(4);
  e.set_now_ns(1000);
  e.mutable_state()->set_what("ossd");
  e.mutable_state()->set_to(to);
  return e;
}

TEST(EventQueue, AFullQueueCountsWhatItDropsAndShowsTheGapInOrder) {
  EventQueue q(16, false, {});
  for (int i = 0; i < 20; ++i) q.push(state_event("on"));
  auto first = q.pop(0ms);
  ASSERT_EQ(first.size(), 16U);  // the capacity, not one more
  EXPECT_EQ(first.front().sequence(), 1U);
  EXPECT_EQ(first.back().sequence(), 16U);
  EXPECT_EQ(q.dropped_total(), 4U);
  q.push(state_event("off"));
  const auto second = q.pop(0ms);
  ASSERT_EQ(second.size(), 2U);
  EXPECT_EQ(second[0].sequence(), 17U);  // no gap in the numbering: the gap is an event
  ASSERT_TRUE(second[0].has_dropped());
  EXPECT_EQ(second[0].dropped().count(), 4U);
  EXPECT_EQ(second[0].now_ns(), 1000);
  EXPECT_EQ(second[1].sequence(), 18U);
  EXPECT_EQ(second[1].state().to(), "off");
}

TEST(EventQueue, CapacityIsClampedAndCloseWakesTheReader) {
  EventQueue q(1, true, {4});
  for (int i = 0; i < 20; ++i) q.push(state_event("on"));
  EXPECT_EQ(q.pop(0ms).size(), EventQueue::kMinCapacity);
  EXPECT_TRUE(q.watches(4));
  EXPECT_FALSE(q.watches(5));
  q.close();
  EXPECT_TRUE(q.pop(10s).empty());  // at once, not after 10 s
  EXPECT_TRUE(q.closed());
}

TEST(EventHub, SnapshotFirstThenOnlyChanges) {
  rs4::device::Rs4Device device;
  EventHub hub;
  hub.watch(4, device);
  EXPECT_TRUE(hub.watches(4));
  EXPECT_FALSE(hub.watches(5));
  auto q = std::make_shared<EventQueue>(64, false, std::vector<std::uint8_t>{});
  hub.subscribe(q, dp::TimePoint{});
  auto events = q->pop(0ms);
  // 12 state items (the scanner's LED3 and LED5 last), one alarm count, one diagnosis.
  ASSERT_EQ(events.size(), 14U);
  EXPECT_EQ(events[0].state().what(), "powered");
  EXPECT_EQ(events[0].state().previous(), "");
  EXPECT_EQ(events[0].state().to(), "off");
  EXPECT_EQ(events[10].state().what(), "led3");
  EXPECT_EQ(events[10].state().to(), "off");
  EXPECT_EQ(events[11].state().what(), "led5");
  EXPECT_EQ(events[11].state().to(), "off");
  EXPECT_TRUE(events[12].has_alarm());
  EXPECT_TRUE(events[13].has_diagnosis());
  hub.poll(dp::TimePoint{});
  EXPECT_TRUE(q->pop(0ms).empty());  // nothing changed
  device.power_on(dp::TimePoint{});
  hub.poll(dp::TimePoint{} + 1ms);
  events = q->pop(0ms);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events[0].state().what(), "powered");
  EXPECT_EQ(events[0].state().previous(), "off");
  EXPECT_EQ(events[0].state().to(), "on");
  EXPECT_EQ(events[0].now_ns(), 1'000'000);
  hub.unsubscribe(q);
  device.power_off(dp::TimePoint{} + 2ms);
  hub.poll(dp::TimePoint{} + 2ms);
  EXPECT_TRUE(q->pop(0ms).empty());  // unsubscribed
}

TEST(TappedStation, ShowsTelegramsToTheStationAsOnTheWire) {
  rs4::device::Rs4Device device;
  device.power_on(dp::TimePoint{});
  TappedStation tap(device);
  EventHub hub;
  tap.set_hub(&hub);
  auto q = std::make_shared<EventQueue>(64, true, std::vector<std::uint8_t>{4});
  hub.subscribe(q, dp::TimePoint{});
  (void)q->pop(0ms);  // the snapshot
  ASSERT_TRUE(hub.wants_telegrams());
  // FDL_Status request to 4 from 1: SD1, DA, SA, FC (request, function 9), FCS, ED.
  const std::vector<std::uint8_t> wire = {0x10, 0x04, 0x01, 0x49, 0x4E, 0x16};
  const auto t = dp::fdl::make_data_telegram(4, 1, dp::fdl::FrameControl{0x49}, std::nullopt,
                                             std::nullopt, {});
  tap.on_telegram(t, dp::TimePoint{} + 5ms);
  const auto events = q->pop(0ms);
  ASSERT_EQ(events.size(), 1U);
  ASSERT_TRUE(events[0].has_telegram());
  EXPECT_EQ(events[0].telegram().direction(), v1::DIRECTION_TO_STATION);
  EXPECT_EQ(events[0].telegram().frame(), std::string(wire.begin(), wire.end()));
  EXPECT_EQ(events[0].telegram().fate(), "delivered");
  EXPECT_EQ(events[0].now_ns(), 5'000'000);
  EXPECT_EQ(tap.address(), device.address());
}

}  // namespace
}  // namespace rs4sim::rpc
