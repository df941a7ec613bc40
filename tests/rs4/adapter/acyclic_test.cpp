// Acyclic services of the adapter ([RS4 manual §5.2]): slot/index,
// block protocol, flow-control byte, adapter commands, RS4 commands, adapter errors.
// Expected bytes are written from the manual's tables, one field per line.
#include "adapter_rig.h"
#include "rs4/adapter/rs4_commands.h"

namespace rs4sim::rs4::adapter::testing {
namespace {

using dp::slave::AcyclicChannel;

Bytes data_of(const dp::slave::AcyclicResult& r) { return Bytes(r.data.begin(), r.data.end()); }

struct Acyclic : ::testing::Test {
  Rig rig;
  void SetUp() override { rig.start(); }
};

TEST_F(Acyclic, OnlySlot0Index2Or3) {
  auto r = rig.read(240, AcyclicChannel::kC1, 1, 3);
  ASSERT_EQ(r.kind, dp::slave::AcyclicResult::Kind::kError);
  EXPECT_EQ(r.error,
            (dp::slave::AcyclicError{0x80, dp::pdu::ErrorCode1{0xB2}, 0x00}));  // invalid slot
  r = rig.read(240, AcyclicChannel::kC1, 0, 4);
  EXPECT_EQ(r.error,
            (dp::slave::AcyclicError{0x80, dp::pdu::ErrorCode1{0xB0}, 0x00}));  // invalid index
  EXPECT_EQ(rig.write(Rig::block({0x90}), 1).error,
            (dp::slave::AcyclicError{0x80, dp::pdu::ErrorCode1{0xB0}, 0x00}));
  EXPECT_EQ(rig.write({0x00, 0x04, 0xFF, 0xFF}).error,
            (dp::slave::AcyclicError{0x80, dp::pdu::ErrorCode1{0xB1}, 0x00}));
  EXPECT_EQ(rig.write(Rig::block({0x90}), 3).kind,
            dp::slave::AcyclicResult::Kind::kData);  // index 3 too
}

TEST_F(Acyclic, EmptyReadIsTheHeaderAlone) {
  EXPECT_EQ(data_of(rig.read()),
            (Bytes{
                0x41,        // flow: bit0 ready, bit1 no payload, bits 6..4 = 100 normal
                0x04,        // block length incl. header
                0xFF, 0xFF,  // last block
            }));
}

TEST_F(Acyclic, GetVersion0x90) {
  ASSERT_EQ(rig.write({0x00, 0x05, 0xFF, 0xFF, 0x90}).kind, dp::slave::AcyclicResult::Kind::kData);
  EXPECT_EQ(data_of(rig.read()), (Bytes{
                                     0x43,        // flow: ready, payload, normal
                                     0x0E,        // 14 bytes
                                     0xFF, 0xFF,  // last block
                                     0x90,        // PROFI_CMD_GET_VERSION
                                     0x01, 0x00,  // PROFIsafe version 1.0
                                     0x01, 0x00,  // PROFIBUS DP version 1.0
                                     0x11,        // DPV1SL components high: C2 + DPC31
                                     0x0D,        // DPV1SL components low: C2, SUB_AL, SUB_CH1
                                     0x00, 0x00, 0x00,  // main interface, function, bugfix
                                 }));
}

TEST_F(Acyclic, LastError0x84AndErrorMemory0x91) {
  rig.run(40ms);
  rig.out_byte = 0x00;  // field pair error 0x2600 (twice, with a valid pair between)
  rig.run(40ms);
  rig.out_byte = 0x01;
  rig.run(40ms);
  rig.out_byte = 0x07;
  rig.run(40ms);
  rig.write(Rig::block({0x84}));
  EXPECT_EQ(rig.read_answer(), (Bytes{
                                   0x84,        // PROFI_CMD_ERROR
                                   0x26, 0x00,  // μC2 error 0x2600
                                   0x00, 0x02,  // μC2 count 2
                                   0x26, 0x00,  // μC1 error 0x2600
                                   0x00, 0x02,  // μC1 count 2 (DECISION: high byte first)
                               }));
  rig.write(Rig::block({0x91}));
  const auto mem = rig.read_answer(40);  // 85 bytes in blocks of 36 payload bytes
  ASSERT_EQ(mem.size(), 85u);
  EXPECT_EQ(mem[0], 0x91);
  EXPECT_EQ(mem[1], 1);      // μC2 write index: 2nd entry
  EXPECT_EQ(mem[3], 0x26);   // μC2 entry 0 hi
  EXPECT_EQ(mem[4], 0x00);   // μC2 entry 0 lo
  EXPECT_EQ(mem[5], 0x26);   // μC2 entry 1
  EXPECT_EQ(mem[7], 0x00);   // μC2 entry 2 empty
  EXPECT_EQ(mem[43], 1);     // μC1 write index
  EXPECT_EQ(mem[45], 0x26);  // μC1 entry 0 hi
}

TEST_F(Acyclic, ErrorMemorySurvivesResetButNotPowerOff) {
  rig.out_byte = 0x00;
  rig.run(40ms);
  rig.write(Rig::block({0x94}));  // PROFI_CMD_RESET
  ASSERT_TRUE(rig.adapter.wants_link_down_until());
  EXPECT_EQ(*rig.adapter.wants_link_down_until(), rig.now + 2s);
  EXPECT_EQ(rig.adapter.led(), LedState::kSteadyInit);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2600);
  rig.advance(2s);
  EXPECT_FALSE(rig.adapter.wants_link_down_until());
  EXPECT_EQ(rig.adapter.counters().resets, 1u);
  EXPECT_EQ(data_of(rig.read()).size(), 4u);  // no answer to 0x94
  rig.adapter.power_cycle(rig.now);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0);
}

TEST_F(Acyclic, BadAdapterCommandsGet0x93) {
  rig.write(Rig::block({0x90, 0x00}));  // 0x90 takes no parameter
  EXPECT_EQ(rig.read_answer(), (Bytes{
                                   0x93,  // error in telegram
                                   0x00,  // wrong length
                                   0x90,  // the faulty command
                               }));
  rig.write(Rig::block({0x92, 0x01, 0x02}));  // mode 2 invalid
  EXPECT_EQ(rig.read_answer(), (Bytes{0x93, 0x01 /* wrong parameter */, 0x92}));
}

TEST_F(Acyclic, Rs4CommandsAreAnsweredByTheRs4) {
  rig.run(31s);
  rig.write(Rig::block({0x24, 0x01}));  // request one scan ([roboticslibrary/rl LeuzeRs4.cpp])
  const auto scan = rig.read_answer();
  ASSERT_FALSE(scan.empty());
  EXPECT_EQ(scan[0], 0x23);  // COM_CMD_MESS_16_RT
  // options (1..3 bytes) + 8 scan number + 1 resolution + 2 start + 2 stop + 529 × 2
  const std::size_t options = scan[1] & 0x03;
  EXPECT_EQ(scan.size(), 1 + options + 8 + 1 + 2 + 2 + 529 * 2);
  rig.write(Rig::block({0x55, 0x01}));  // unknown to the RS4
  const auto err = rig.read_answer();
  ASSERT_GE(err.size(), 8u);
  EXPECT_EQ(err[0], 0x53);  // COM_CMD_ERROR_OCCURE
  EXPECT_EQ(Bytes(err.end() - 6, err.end()),
            (Bytes{
                0x05, 0x01,  // error number: unknown command (EXTENSION)
                0x00, 0x55,  // parameter: the command byte
                0x00, 0x05,  // function: command interpreter
            }));
}

TEST_F(Acyclic, AliveTelegramCarriesTheOptionBytes) {
  rig.run(31s);
  rig.write(Rig::block({0x14, 0x01}));
  EXPECT_EQ(
      rig.read_answer(),
      (Bytes{
          0x14,  // COM_CMD_ALIVE
          0x0B,  // option 1: 3 option bytes, state 010 measuring
          0x90,  // option 2: bit 4 restart interlock (start interlock), bit 7 option 3 follows
          0x81,  // option 3: field pair 1, bit 7
      }));
  rig.restart_pulse();
  rig.write(Rig::block({0x14, 0x01}));
  // as in [roboticslibrary/rl LeuzeRs4.cpp]
  EXPECT_EQ(rig.read_answer(), (Bytes{0x14, 0x0B, 0x80, 0x81}));
}

TEST_F(Acyclic, OutOfSequenceBlockGives2A0B) {
  rig.write({0x00, 0x05, 0x00, 0x01, 0x90});  // block 1 without block 0
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2A0B);
}

TEST_F(Acyclic, CommandOf1100BytesGives2A06) {
  Bytes blk(240, 0x55);
  blk[0] = 0x00;
  blk[1] = 240;
  for (std::uint16_t n = 0; n < 4; ++n) {  // 4 × 236 = 944 bytes
    blk[2] = 0;
    blk[3] = static_cast<std::uint8_t>(n);
    rig.write(blk);
  }
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0);
  blk[2] = blk[3] = 0xFF;  // last: 944 + 236 = 1180 ≥ 1100
  rig.write(blk);
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2A06);
}

TEST_F(Acyclic, MultiBlockCommandIsReassembled) {
  rig.write({0x00, 0x05, 0x00, 0x00, 0x24});  // block 0: CMD
  rig.write({0x00, 0x05, 0xFF, 0xFF, 0x01});  // last block: option 1
  const auto a = rig.read_answer();
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a[0], 0x53);  // RS4 still booting: "no scan" error telegram
  EXPECT_EQ(a[a.size() - 6], 0x05);
  EXPECT_EQ(a[a.size() - 5], 0x02);
}

TEST_F(Acyclic, UnreadResultsFillTheReadBuffers2A05) {
  for (int i = 0; i < 4; ++i) rig.write(Rig::block({0x90}));
  EXPECT_EQ(rig.adapter.flow_byte(AcyclicChannel::kC1, false) & 0x01, 0);  // not ready
  rig.write(Rig::block({0x90}));
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0x2A05);
  EXPECT_EQ(rig.adapter.pending_answers(AcyclicChannel::kC1), 4u);
  const auto first = data_of(rig.read());
  EXPECT_EQ(first[0], 0x43);  // the buffer is free again once this block is fetched
}

TEST_F(Acyclic, WriteWhenNotReadyGives2A04) {
  Rig fresh;
  fresh.adapter.power_on(fresh.now);
  fresh.advance(1s);  // adapter initialising: flow 001, bit 0 = 0
  EXPECT_EQ(fresh.adapter.flow_byte(AcyclicChannel::kC2, false), 0x10);
  fresh.write(Rig::block({0x24, 0x01}), 2, AcyclicChannel::kC2);
  EXPECT_EQ(fresh.adapter.error_memory().last_error().uc2_error, 0x2A04);
}

TEST_F(Acyclic, FlowStates) {
  EXPECT_EQ(rig.adapter.flow_byte(AcyclicChannel::kC1, false), 0x41);  // 100 normal
  rig.run(31s);
  ASSERT_FALSE(rig.adapter.proxy_sync_started(rig.now));
  EXPECT_EQ(rig.adapter.flow_byte(AcyclicChannel::kC1, false), 0x31);  // 011 proxy busy
  ASSERT_FALSE(rig.adapter.proxy_sync_succeeded(rig.now));
  rig.adapter.attach_pc_adapter(rig.now);
  EXPECT_EQ(rig.adapter.flow_byte(AcyclicChannel::kC1, false), 0x20);  // 010 PC adapter
  rig.adapter.detach_pc_adapter(rig.now);
  rig.adapter.on_state_change(dp::slave::State::kDataExch, dp::slave::State::kWaitPrm,
                              dp::slave::TransitionReason::kWatchdog, rig.now);
  EXPECT_EQ(rig.adapter.flow_byte(AcyclicChannel::kC2, false), 0x51);  // 101 no connection
}

TEST_F(Acyclic, WritesIgnoredWhilePcAdapterAttached) {
  rig.adapter.attach_pc_adapter(rig.now);
  EXPECT_EQ(rig.write(Rig::block({0x90})).kind, dp::slave::AcyclicResult::Kind::kData);
  EXPECT_EQ(rig.adapter.counters().writes_ignored, 1u);
  EXPECT_EQ(data_of(rig.read()), (Bytes{0x20, 0x04, 0xFF, 0xFF}));  // flow 010, nothing
  EXPECT_EQ(rig.adapter.error_memory().last_error().uc2_error, 0);  // without error
}

TEST_F(Acyclic, GetRs4DataOneShotAndPermanent) {
  rig.run(31s);
  rig.write(Rig::block({0x92, 0x01, 0x00}));  // measurement, once
  auto t = rig.read_answer();
  ASSERT_FALSE(t.empty());
  EXPECT_EQ(t[0], 0x23);
  rig.run(200ms);
  EXPECT_EQ(data_of(rig.read()).size(), 4u);  // once: nothing more
  rig.write(Rig::block({0x92, 0x02, 0x01}));  // alive, permanent
  t = rig.read_answer();
  ASSERT_FALSE(t.empty());
  EXPECT_EQ(t[0], 0x14);
  rig.run(100ms);
  t = rig.read_answer();
  ASSERT_FALSE(t.empty());
  EXPECT_EQ(t[0], 0x14);
  rig.write(Rig::block({0x92, 0x00, 0x00}));  // mask 0: stop
  rig.run(100ms);
  EXPECT_EQ(data_of(rig.read()).size(), 4u);
}

TEST_F(Acyclic, ErrorTelegramsGoToTheSecondBuffer) {
  rig.run(31s);
  rig.write(Rig::block({0x92, 0x09, 0x01}));  // measurement + error, permanent
  ASSERT_TRUE(rig.adapter.scanner().inject_fault(scanner::Fault::kMotorSpeed, rig.now));
  rig.run(100ms);
  EXPECT_EQ(rig.adapter.buffered_events(), 1u);
  auto t = rig.read_answer();  // the error first
  ASSERT_GE(t.size(), 8u);
  EXPECT_EQ(t[0], 0x53);
  EXPECT_EQ(t[t.size() - 6], 0x02);  // RS4 fault 0x0201 motor speed
  EXPECT_EQ(t[t.size() - 5], 0x01);
  t = rig.read_answer();  // then the measurement
  ASSERT_FALSE(t.empty());
  EXPECT_EQ(t[0], 0x23);
}

}  // namespace
}  // namespace rs4sim::rs4::adapter::testing
