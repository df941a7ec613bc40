// MSAC_C2 ([IEC 61158-6-3 MSAC_C2]): RM on SAP 49, one connection on SAP 48,
// Initiate/Abort/Read/Write, second Initiate refused with RS, idle timeout on the manual clock.
#include "tests/dp/slave/slave_harness.h"

#include <chrono>

namespace rs4sim::dp::testing {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

using std::chrono::milliseconds;

// Class-2 master 1 (SA 0x81) from SAP 50, with its own FCB sequence.
class C2Master {
 public:
  Bytes frame(std::uint8_t dsap, const Bytes& du, std::uint8_t sa = 0x81) {
    std::uint8_t fc = 0x6C;
    if (!first_) fc = fcb_ ? 0x5C : 0x7C;
    if (!first_) fcb_ = !fcb_;
    first_ = false;
    Bytes body{0x85, sa, fc, dsap, 0x32};
    body.insert(body.end(), du.begin(), du.end());
    return sd2(body);
  }
  static Bytes reply(std::uint8_t ssap, const Bytes& du) {
    Bytes body{0x81, 0x85, 0x08, 0x32, ssap};
    body.insert(body.end(), du.begin(), du.end());
    return sd2(body);
  }

 private:
  bool first_ = true;
  bool fcb_ = true;  // FCB of the last frame
};

const Bytes kInitiate{0x57, 0x00, 0x00, 0x00, 0x00, 0x64,  // Send_Timeout 100 × 10 ms = 1 s
                      0x01, 0x00,                          // Features_Supported
                      0x00, 0x00,                          // Profile_Features_Supported
                      0x00, 0x00,                          // Profile_Ident_Number
                      0x00, 0x02,                          // S_Type 0, S_Len 2
                      0x00, 0x02,                          // D_Type 0, D_Len 2
                      0x01, 0x02,                          // S_Addr: API 1, SCL 2
                      0x03, 0x04};                         // D_Addr: API 3, SCL 4
const Bytes kRsToMaster1{0x10, 0x01, 0x05, 0x03, 0x09, 0x16};

void connect(SlaveHarness& h, C2Master& m) {
  // RM answers at once with `56 SAP Send_Timeout`: SAP 48, 100 × 10 ms ([IEC 61158-6-3 MSAC_C2]).
  EXPECT_EQ(h.send(m.frame(0x31, kInitiate)), C2Master::reply(0x31, {0x56, 0x30, 0x00, 0x64}));
  EXPECT_EQ(h.send(m.frame(0x30, {})),
            C2Master::reply(0x30, {0x57,
                                   0xF4,        // Max_Len_Data_Unit 240 + 4
                                   0x01, 0x00,  // Features_Supported
                                   0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0x00, 0x02, 0x03,
                                   0x04,           // S_Addr = the request's D_Addr
                                   0x01, 0x02}));  // D_Addr = the request's S_Addr
  EXPECT_TRUE(h.slave.c2_connected());
}

TEST(SlaveC2, InitiateReadWriteAbort) {
  SlaveHarness h;
  C2Master m;
  connect(h, m);
  ASSERT_EQ(h.app.c2_events, std::vector<C2Event>{C2Event::kConnected});
  EXPECT_EQ(h.send(m.frame(0x30, {0x5E, 0x00, 0x02, 0x04})), kSc);
  ASSERT_EQ(h.app.acyclic.size(), 1U);
  EXPECT_EQ(h.app.acyclic[0].req.channel, AcyclicChannel::kC2);
  EXPECT_EQ(h.send(m.frame(0x30, {})), C2Master::reply(0x30, {0x5E, 0x00, 0x02, 0x02, 0xAB, 0xCD}));
  h.send(m.frame(0x30, {0x5F, 0x00, 0x02, 0x01, 0x99}));
  EXPECT_EQ(h.send(m.frame(0x30, {})), C2Master::reply(0x30, {0x5F, 0x00, 0x02, 0x01}));
  h.send(m.frame(0x30, {0x5F, 0x00, 0x03, 0x01, 0x98}));
  ASSERT_EQ(h.app.acyclic.size(), 3U);
  EXPECT_TRUE(h.app.acyclic[1].req.first_write_after_initiate);
  EXPECT_FALSE(h.app.acyclic[2].req.first_write_after_initiate);
  h.send(m.frame(0x30, {}));
  EXPECT_EQ(h.send(m.frame(0x30, {0x58, 0x00, 0x20, 0x00})), kSc);  // Abort by the user
  EXPECT_FALSE(h.slave.c2_connected());
  EXPECT_EQ(h.app.c2_events.back(), C2Event::kAbortedByMaster);
  EXPECT_EQ(h.send(m.frame(0x30, {})), kRsToMaster1);
}

TEST(SlaveC2, DataTransportRoundTrip) {
  SlaveHarness h;
  C2Master m;
  connect(h, m);
  const Bytes transport{0x51,  // Data_Transport
                        0x00,  // slot 0
                        0x05,  // index 5
                        0x02,  // 2 data bytes
                        0xAA, 0xBB};
  EXPECT_EQ(h.send(m.frame(0x30, transport)), kSc);
  ASSERT_EQ(h.app.acyclic.size(), 1U);
  EXPECT_EQ(h.app.acyclic[0].req.service, AcyclicService::kDataTransport);
  EXPECT_EQ(h.app.acyclic[0].data, (Bytes{0xAA, 0xBB}));
  EXPECT_FALSE(h.app.acyclic[0].req.first_write_after_initiate);
  EXPECT_EQ(h.send(m.frame(0x30, {})), C2Master::reply(0x30, {0x51, 0x00, 0x05, 0x02, 0xAB, 0xCD}));
  // Length ≠ data: D1 80 B3 00.
  h.send(m.frame(0x30, {0x51, 0x00, 0x05, 0x03, 0xAA}));
  EXPECT_EQ(h.send(m.frame(0x30, {})), C2Master::reply(0x30, {0xD1, 0x80, 0xB3, 0x00}));
}

TEST(SlaveC2, SecondInitiateIsRefusedWithRs) {
  SlaveHarness h;
  C2Master m;
  connect(h, m);
  C2Master other;  // master 3
  EXPECT_EQ(h.send(other.frame(0x31, kInitiate, 0x83)),
            (Bytes{0x10, 0x03, 0x05, 0x03, 0x0B, 0x16}));
  EXPECT_EQ(h.send(other.frame(0x30, {0x5E, 0x00, 0x02, 0x04}, 0x83)),
            (Bytes{0x10, 0x03, 0x05, 0x03, 0x0B, 0x16}));  // not its connection
  EXPECT_EQ(h.app.c2_events.size(), 1U);
}

TEST(SlaveC2, IdleTimeoutOnTheManualClock) {
  SlaveHarness h;
  C2Master m;
  connect(h, m);
  h.advance(milliseconds(999));
  EXPECT_TRUE(h.slave.c2_connected());
  EXPECT_EQ(h.send(m.frame(0x30, {0x48, 0x00})), kSc);  // Idle retriggers
  h.advance(milliseconds(999));
  EXPECT_TRUE(h.slave.c2_connected());
  h.advance(milliseconds(1));
  EXPECT_FALSE(h.slave.c2_connected());
  EXPECT_EQ(h.app.c2_events.back(), C2Event::kTimedOut);
  EXPECT_EQ(h.send(m.frame(0x30, {})), kRsToMaster1);
  // The RM is loaded again: a new Initiate works.
  connect(h, m);
}

TEST(SlaveC2, InvalidInitiateIsAbortedWithTheReason) {
  SlaveHarness h;
  C2Master m;
  Bytes bad = kInitiate;
  bad[4] = 0x00;
  bad[5] = 0x00;  // Send_Timeout 0
  EXPECT_EQ(h.send(m.frame(0x31, bad)), C2Master::reply(0x31, {0x56, 0x30, 0x00, 0x64}));
  EXPECT_EQ(h.send(m.frame(0x30, {})),
            C2Master::reply(0x30, {0x58,
                                   0x00,  // Subnet none
                                   0x16,  // Instance MSAC_C2 (01), reason 6 Send_Timeout too small
                                   0x00}));
  EXPECT_FALSE(h.slave.c2_connected());
  Bytes short_addr = kInitiate;
  short_addr.pop_back();  // D_Len says 2, 1 present
  h.send(m.frame(0x31, short_addr));
  EXPECT_EQ(h.send(m.frame(0x30, {})), C2Master::reply(0x30, {0x58, 0x00, 0x17, 0x00}));
}

TEST(SlaveC2, UnknownPduAbortsAndOffWhenNotSupported) {
  SlaveHarness h;
  C2Master m;
  connect(h, m);
  EXPECT_EQ(h.send(m.frame(0x30, {0x5C, 0x00, 0x01, 0x05})), kSc);  // Alarm_Ack is C1 only
  EXPECT_EQ(h.send(m.frame(0x30, {})), C2Master::reply(0x30, {0x58, 0x00, 0x12, 0x00}));
  EXPECT_FALSE(h.slave.c2_connected());

  Config cfg = example_config();
  cfg.c2_supported = false;
  SlaveHarness off(cfg);
  C2Master m2;
  EXPECT_EQ(off.send(m2.frame(0x31, kInitiate)), kRsToMaster1);
}

}  // namespace
}  // namespace rs4sim::dp::testing
