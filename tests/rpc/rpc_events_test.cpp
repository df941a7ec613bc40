// Observation.StreamEvents end to end on a real server on loopback (docs/rpc.md "Event
// stream"): the snapshot, the state changes of a boot and a protective-field violation in
// the manual's order [RS4 manual §4.3], every telegram with its direction and wire bytes,
// a slow client's EventsDropped, and the bad-input statuses.
#include "rs4_fixture.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>

namespace rs4sim::rpc {
namespace {

class RpcEventsTest : public RpcRs4Test {
 protected:
  std::unique_ptr<grpc::ClientReader<v1::Event>> open(grpc::ClientContext& ctx,
                                                      const v1::StreamEventsRequest& req) {
    ctx.set_deadline(std::chrono::system_clock::now() + 20s);
    return observation_stub_->StreamEvents(&ctx, req);
  }
  // Reads until a StateChange `what` → `to` arrived; the StateChanges read on the way.
  static std::vector<v1::StateChange> read_until(grpc::ClientReader<v1::Event>& reader,
                                                 const std::string& what, const std::string& to) {
    std::vector<v1::StateChange> seen;
    v1::Event e;
    while (reader.Read(&e)) {
      if (!e.has_state()) continue;
      seen.push_back(e.state());
      if (e.state().what() == what && e.state().to() == to) return seen;
    }
    ADD_FAILURE() << "stream ended before " << what << " → " << to << ": "
                  << reader.Finish().error_message();
    return seen;
  }
  // The snapshot a new stream opens with, up to `items` states by name: every event numbered
  // in order from 1, of station 4, every item with from = "" (nothing is advanced before it
  // has arrived).
  static std::map<std::string, std::string> read_snapshot(grpc::ClientReader<v1::Event>& reader,
                                                          std::size_t items) {
    std::map<std::string, std::string> snapshot;
    v1::Event e;
    std::uint64_t sequence = 0;
    while (snapshot.size() < items && reader.Read(&e)) {
      EXPECT_EQ(e.sequence(), ++sequence);
      EXPECT_EQ(e.address(), 4U);
      if (e.has_state()) {
        EXPECT_EQ(e.state().previous(), "");
        snapshot[e.state().what()] = e.state().to();
      }
    }
    return snapshot;
  }
  grpc::Status stream_status(const v1::StreamEventsRequest& req) {
    grpc::ClientContext ctx;
    auto reader = open(ctx, req);
    v1::Event e;
    EXPECT_FALSE(reader->Read(&e));
    return reader->Finish();
  }
};

TEST_F(RpcEventsTest, SnapshotThenTheBootAndAViolationInOrder) {
  grpc::ClientContext ctx;
  v1::StreamEventsRequest req;
  auto reader = open(ctx, req);
  auto snapshot = read_snapshot(*reader, 12);
  EXPECT_EQ(snapshot["powered"], "on");
  EXPECT_EQ(snapshot["ossd"], "off");
  EXPECT_EQ(snapshot["dp-state"], "Wait_Prm");
  EXPECT_EQ(snapshot["led3"], "off");
  EXPECT_EQ(snapshot["led5"], "off");

  boot();
  const auto to_exchange = read_until(*reader, "dp-state", "Data_Exch");
  EXPECT_FALSE(to_exchange.empty());
  const auto to_ossd = read_until(*reader, "ossd", "on");
  EXPECT_EQ(to_ossd.back().previous(), "off");

  v1::AddObstacleResponse obstacle;
  ASSERT_TRUE(violate_field(v1::FIELD_KIND_PROTECTIVE, obstacle).ok());
  ASSERT_TRUE(run_until(v1::CONDITION_OSSD_OFF, 500));
  const auto off = read_until(*reader, "ossd", "off");
  EXPECT_EQ(off.back().previous(), "on");
  ctx.TryCancel();
  EXPECT_EQ(reader->Finish().error_code(), grpc::StatusCode::CANCELLED);
}

// The scanner's LED3 in the stream [RS4 manual §4.3]: red when the restart button is held
// (Device.SetRestartButton), off at the release, with the OSSD's own changes around it.
TEST_F(RpcEventsTest, Led3FollowsTheRestartButton) {
  boot();
  grpc::ClientContext ctx;
  v1::StreamEventsRequest req;
  auto reader = open(ctx, req);
  // The call returns before the server has subscribed; the snapshot's LED3 item says it has.
  // A press before that would arrive inside the snapshot (from "") instead of as a change.
  const auto snapshot = read_until(*reader, "led3", "off");
  ASSERT_FALSE(snapshot.empty());
  ASSERT_EQ(snapshot.back().previous(), "");
  const auto button = [&](bool pressed) { ASSERT_TRUE(set_restart_button(pressed).ok()); };
  button(true);
  const auto red = read_until(*reader, "led3", "red");
  ASSERT_FALSE(red.empty());
  EXPECT_EQ(red.back().previous(), "off");
  advance(300);
  button(false);
  const auto off = read_until(*reader, "led3", "off");
  ASSERT_FALSE(off.empty());
  EXPECT_EQ(off.back().previous(), "red");
  std::vector<v1::StateChange> seen = red;
  seen.insert(seen.end(), off.begin(), off.end());
  const bool ossd_went_off = std::any_of(seen.begin(), seen.end(), [](const v1::StateChange& c) {
    return c.what() == "ossd" && c.to() == "off";
  });
  EXPECT_TRUE(ossd_went_off) << "the OSSD is off while the button is held";
  ctx.TryCancel();
  (void)reader->Finish();
}

// The PLC's side of the simulated bus: a CRC2 error passivates the F-host, the PLC program
// reads the fail-safe value 0 instead of the RS4's input byte, after good PDUs it waits for
// the operator (ACK_REQ), and Faults.AcknowledgeReintegration (ACK_REI) brings it back to RUN
// [RS4 manual §7.3.2, IEC 61784-3-3 CRC].
TEST_F(RpcEventsTest, TheFHostsStateAndThePlcInputByteFollowAPassivation) {
  grpc::ClientContext ctx;
  v1::StreamEventsRequest req;
  auto reader = open(ctx, req);
  auto snapshot = read_snapshot(*reader, 14);
  EXPECT_EQ(snapshot["plc-input-byte"], "00");  // no data exchange yet
  EXPECT_NE(snapshot["fhost-state"], "run");
  boot();
  read_until(*reader, "fhost-state", "run");
  advance(50);  // the PLC sees the RS4's byte a master cycle later
  // In RUN the PLC reads the RS4's own input byte (with the OSSD bit 7 set after the boot).
  const auto rs4 = state();
  ASSERT_TRUE(rs4.ossd());
  char sent[3];
  std::snprintf(sent, sizeof sent, "%02x", rs4.input_byte());
  EXPECT_FALSE(read_until(*reader, "plc-input-byte", sent).empty());
  EXPECT_EQ(rs4.plc().input_byte(), rs4.input_byte());

  grpc::ClientContext c2;
  v1::SafetyFaultRequest fault;
  fault.set_address(4);
  fault.set_fault(v1::SAFETY_FAULT_CORRUPT_CRC2);
  fault.set_count(1);
  v1::Empty empty;
  ASSERT_TRUE(faults_stub_->InjectSafetyFault(&c2, fault, &empty).ok());
  advance(500);
  const auto acknowledge = [&] {
    grpc::ClientContext c3;
    v1::StationRequest station;
    station.set_address(4);
    return faults_stub_->AcknowledgeReintegration(&c3, station, &empty);
  };
  std::vector<std::pair<std::string, std::string>> after;  // (what, to) of the F-host items
  bool acknowledged = false;
  v1::Event e;
  while (reader->Read(&e)) {
    if (!e.has_state()) continue;
    const auto& c = e.state();
    if (c.what() != "fhost-state" && c.what() != "plc-input-byte") continue;
    after.emplace_back(c.what(), c.to());
    if (c.what() == "fhost-state" && c.to() == "ack-required" && !acknowledged) {
      // This segment does not acknowledge by itself: the operator does, through the API.
      ASSERT_TRUE(acknowledge().ok());
      acknowledged = true;
      advance(100);
    }
    if (c.what() == "fhost-state" && c.to() == "run") break;
  }
  using Item = std::pair<std::string, std::string>;
  ASSERT_GE(after.size(), 4U);
  EXPECT_EQ(after.front(), (Item{"fhost-state", "passivated"}));
  EXPECT_NE(std::find(after.begin(), after.end(), Item{"plc-input-byte", "00"}), after.end());
  EXPECT_NE(std::find(after.begin(), after.end(), Item{"fhost-state", "ack-required"}),
            after.end());
  EXPECT_EQ(after.back(), (Item{"fhost-state", "run"}));
  // Nothing to acknowledge in RUN: a specific refusal.
  const auto again = acknowledge();
  EXPECT_EQ(again.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(again.error_message().find("not ack-required"), std::string::npos)
      << again.error_message();
  ctx.TryCancel();
  (void)reader->Finish();
}

TEST_F(RpcEventsTest, EveryTelegramWithDirectionTimeAndWireBytes) {
  boot();
  grpc::ClientContext ctx;
  v1::StreamEventsRequest req;
  req.add_addresses(4);
  req.set_telegrams(true);
  auto reader = open(ctx, req);
  v1::Event e;
  // The call returns before the server has subscribed; the first event (the snapshot) says it
  // has. Advancing before that could run the 100 ms before the subscription: no telegrams.
  ASSERT_TRUE(reader->Read(&e));
  advance(100);
  int to_station = 0;
  int from_station = 0;
  std::int64_t last_ns = 0;
  while (to_station < 5 || from_station < 5) {
    ASSERT_TRUE(reader->Read(&e));
    if (!e.has_telegram()) continue;
    const auto& t = e.telegram();
    ASSERT_FALSE(t.frame().empty());
    // SD1 10, SD2 68, SD3 A2, SD4 DC, short acknowledgement E5 [IEC 61158-4-3 frame formats].
    const auto sd = static_cast<std::uint8_t>(t.frame()[0]);
    EXPECT_TRUE(sd == 0x10 || sd == 0x68 || sd == 0xA2 || sd == 0xDC || sd == 0xE5) << int(sd);
    EXPECT_EQ(t.fate(), "delivered");
    EXPECT_GE(e.now_ns(), last_ns);
    last_ns = e.now_ns();
    if (t.direction() == v1::DIRECTION_TO_STATION) {
      ++to_station;
      if (sd == 0x68) {
        EXPECT_EQ(static_cast<std::uint8_t>(t.frame()[4]) & 0x7F, 4);  // DA (bit 7: SAPs)
      }
    } else {
      ASSERT_EQ(t.direction(), v1::DIRECTION_FROM_STATION);
      ++from_station;
    }
  }
  ctx.TryCancel();
  (void)reader->Finish();
}

TEST_F(RpcEventsTest, ASlowClientGetsEventsDroppedNotUnboundedMemory) {
  grpc::ClientContext ctx;
  v1::StreamEventsRequest req;
  req.set_telegrams(true);
  req.set_queue_capacity(16);
  auto reader = open(ctx, req);
  v1::Event e;
  ASSERT_TRUE(reader->Read(&e));  // subscribed: the snapshot is on its way
  // ≈6000 cycles of telegrams while nobody reads: more than the 16 queued plus what the
  // transport buffers (HTTP/2 flow-control window, socket buffers) hold.
  advance(60'000);
  std::uint64_t dropped = 0;
  std::uint64_t sequence = e.sequence();
  while (dropped == 0 && reader->Read(&e)) {
    EXPECT_EQ(e.sequence(), ++sequence);  // the gap is an event, not a hole
    if (e.has_dropped()) dropped = e.dropped().count();
  }
  // How many are dropped depends on how fast the server's writer drains into the transport
  // (an ASan build is slower): that some are, and are counted, is the behaviour.
  EXPECT_GT(dropped, 0U);
  ctx.TryCancel();
  (void)reader->Finish();
}

TEST_F(RpcEventsTest, BadInputGetsASpecificStatus) {
  v1::StreamEventsRequest req;
  req.set_queue_capacity(5);
  auto s = stream_status(req);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "queue_capacity");
  req.set_queue_capacity(0);
  req.add_addresses(4);
  req.add_addresses(300);
  s = stream_status(req);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "addresses[1]");
  req.set_addresses(1, 9);
  s = stream_status(req);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_NE(s.error_message().find("station 9"), std::string::npos) << s.error_message();
}

}  // namespace
}  // namespace rs4sim::rpc
