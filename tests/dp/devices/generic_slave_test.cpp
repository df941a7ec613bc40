// The generic virtual slave driven by the worked example (
// [docs/references.md#dp-worked-example]: master 2, slave 5, ident 0x1234, Cfg 10 20) and the DPV1
// examples of [IEC 61158-6-3 MSAC_C1 polling, DPV1 alarms]. Request and reply bytes are written
// from the cited sources, one field per line where new.
#include "dp/devices/generic_slave.h"

#include "tests/dp/devices/script_master.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::devices {
namespace {

using testing::Bytes;
using testing::ScriptMaster;

constexpr std::uint8_t kSapC1 = 51;  // MSAC_C1 ([IEC 61158-6-3 SAP assignment])

class GenericSlaveSpec : public ::testing::Test {
 protected:
  void SetUp() override {
    bus.attach(master);
    bus.attach(slave);
    bus.start();
  }
  // [docs/references.md#dp-worked-example] steps up to Data_Exchange, checking every reply against
  // the expected bytes.
  void start_up() {
    EXPECT_EQ(
        master.send_frame({0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x6D, 0x3C, 0x3E, 0xEE, 0x16}),
        (Bytes{0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C,  // SD2, DA 2, SA 5, DL, SAPs
               0x02,        // Station_Status_1: Station_Not_Ready
               0x05,        // Station_Status_2: Prm_Req + always-1 bit
               0x00,        // Station_Status_3
               0xFF,        // Master_Add: not parameterised
               0x12, 0x34,  // Ident_Number
               0xD5, 0x16}));
    EXPECT_EQ(master.send_frame({0x68, 0x0F, 0x0F, 0x68, 0x85, 0x82, 0x5D, 0x3D, 0x3E, 0x88, 0x0A,
                                 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x20, 0x00, 0x63, 0x16}),
              Bytes{0xE5});  // Set_Prm → SC
    EXPECT_EQ(master.send_frame(
                  {0x68, 0x07, 0x07, 0x68, 0x85, 0x82, 0x7D, 0x3E, 0x3E, 0x10, 0x20, 0x30, 0x16}),
              Bytes{0xE5});  // Chk_Cfg 10 20 → SC
    EXPECT_EQ(master.send_frame({0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x5D, 0x3C, 0x3E, 0xDE, 0x16}),
              (Bytes{0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x3E, 0x3C,
                     0x00,        // Station_Status_1: ready
                     0x0C,        // Station_Status_2: WD_On + always-1
                     0x00, 0x02,  // Station_Status_3, Master_Add = 2
                     0x12, 0x34, 0xDD, 0x16}));
  }

  ManualClock clock;
  link::MemoryBus bus{clock};
  ScriptMaster master{bus, 2};
  GenericSlave slave{{5, 0x1234, {0x10, 0x20}, true}};
};

TEST_F(GenericSlaveSpec, StartUpAndLoopbackDataExchange) {
  start_up();
  EXPECT_EQ(slave.slave().state(), dp::slave::State::kDataExch);
  // [docs/references.md#dp-worked-example] "M→S DX" out = A5; the generic device loops it back: in
  // = A5.
  EXPECT_EQ(master.send_frame({0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x7D, 0xA5, 0x29, 0x16}),
            (Bytes{0x68, 0x04, 0x04, 0x68,
                   0x02,  // DA master
                   0x05,  // SA slave
                   0x08,  // FC: DL
                   0xA5,  // input byte = looped-back output
                   0xB4,  // FCS 02+05+08+A5
                   0x16}));
  EXPECT_EQ(slave.device().exchanges(), 1U);
}

TEST_F(GenericSlaveSpec, WrongConfigurationIsACfgFault) {
  master.send_frame({0x68, 0x05, 0x05, 0x68, 0x85, 0x82, 0x6D, 0x3C, 0x3E, 0xEE, 0x16});
  master.send_frame({0x68, 0x0F, 0x0F, 0x68, 0x85, 0x82, 0x5D, 0x3D, 0x3E, 0x88, 0x0A,
                     0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x20, 0x00, 0x63, 0x16});
  // Chk_Cfg 10 21 (1 B in, 2 B out) instead of 10 20.
  // SC = "received" only ([IEC 61158-4-3 short acknowledgement])
  EXPECT_EQ(master.request(5, 62, 62, {0x10, 0x21}), Bytes{0xE5});
  const Bytes diag = master.request(5, 60, 62, {});
  ASSERT_GE(diag.size(), 15U);
  EXPECT_EQ(diag[9] & 0x04, 0x04) << "Station_Status_1 bit 2 Cfg_Fault "
                                     "([IEC 61158-6-3 Slave_Diag])";
  EXPECT_NE(slave.slave().state(), dp::slave::State::kDataExch);
}

TEST_F(GenericSlaveSpec, DataExchangeBeforeStartUpIsAnsweredRs) {
  // [docs/references.md#dp-worked-example] "S→M RS (not in DX)": 10 02 05 03 0A 16
  EXPECT_EQ(master.send_frame({0x68, 0x04, 0x04, 0x68, 0x05, 0x02, 0x6D, 0xA5, 0x19, 0x16}),
            (Bytes{0x10,  // SD1
                   0x02,  // DA
                   0x05,  // SA
                   0x03,  // FC: RS, SAP not enabled
                   0x0A,  // FCS
                   0x16}));
}

TEST_F(GenericSlaveSpec, Dpv1WriteThenReadOfARecord) {
  start_up();
  // Write.req slot 0 index 1, 2 bytes AB CD ([IEC 61158-6-3 MSAC_C1]); SC, then the echo on a poll
  // ([IEC 61158-6-3 MSAC_C1 polling]).
  EXPECT_EQ(master.request(5, kSapC1, kSapC1, {0x5F, 0x00, 0x01, 0x02, 0xAB, 0xCD}), Bytes{0xE5});
  const Bytes write_res = master.request(5, kSapC1, kSapC1, {});
  EXPECT_EQ(write_res, (Bytes{0x68, 0x09, 0x09, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33, 0x5F, 0x00,
                              0x01, 0x02,  // Write.res+: fn, slot, index, length
                              0xD7,        // FCS 82+85+08+33+33+5F+00+01+02 mod 256
                              0x16}));
  // [IEC 61158-6-3 MSAC_C1 polling] example: Read slot 0 index 1 up to 16 bytes → SC → poll → 2
  // bytes AB CD.
  EXPECT_EQ(master.request(5, kSapC1, kSapC1, {0x5E, 0x00, 0x01, 0x10}), Bytes{0xE5});
  EXPECT_EQ(master.request(5, kSapC1, kSapC1, {}),
            (Bytes{0x68, 0x0B, 0x0B, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33, 0x5E, 0x00, 0x01, 0x02,
                   0xAB, 0xCD, 0x4E, 0x16}));
  ASSERT_NE(slave.device().record(0, 1), nullptr);
}

TEST_F(GenericSlaveSpec, Dpv1ReadOfAnUnknownRecordIsInvalidIndex) {
  start_up();
  EXPECT_EQ(master.request(5, kSapC1, kSapC1, {0x5E, 0x00, 0x07, 0x10}), Bytes{0xE5});
  // [IEC 61158-6-3 MSAC_C1 polling] negative example: 68 09 09 68 82 85 08 33 33 DE 80 B0 00 83 16
  EXPECT_EQ(master.request(5, kSapC1, kSapC1, {}),
            (Bytes{0x68, 0x09, 0x09, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33,
                   0xDE,  // Read negative (0x5E | 0x80)
                   0x80,  // Error_Decode DPV1
                   0xB0,  // Error_Code_1: access, invalid index
                   0x00,  // Error_Code_2
                   0x83, 0x16}));
}

TEST_F(GenericSlaveSpec, AlarmRequestedByAWriteMakesTheFullRoundTrip) {
  master.request(5, 60, 62, {});
  // Set_Prm as [docs/references.md#dp-worked-example] but DPV1_Status_2 = 0x60: diagnostic +
  // process alarms enabled ([IEC 61158-6-3 DPV1_Status]).
  EXPECT_EQ(master.request(5, 61, 62, {0x88, 0x0A, 0x01, 0x0B, 0x12, 0x34, 0x00, 0x80, 0x60, 0x00}),
            Bytes{0xE5});
  EXPECT_EQ(master.request(5, 62, 62, {0x10, 0x20}), Bytes{0xE5});
  master.request(5, 60, 62, {});
  EXPECT_EQ(master.request(5, std::nullopt, std::nullopt, {0x01}).at(6), 0x08);  // DX: DL
  // Write to the trigger record (slot 0, index 200) with one user byte 0x99.
  EXPECT_EQ(master.request(5, kSapC1, kSapC1,
                           {0x5F, 0x00, GenericDevice::kAlarmTriggerIndex, 0x01, 0x99}),
            Bytes{0xE5});
  EXPECT_EQ(master.request(5, kSapC1, kSapC1, {}).at(9), 0x5F);  // Write.res+
  // The next Data_Exchange reply is high priority: FC = DH ([IEC 61158-6-3 Data_Exchange]).
  EXPECT_EQ(master.request(5, std::nullopt, std::nullopt, {0x01}).at(6), 0x0A);
  const Bytes diag = master.request(5, 60, 62, {});
  // SD2 header (4) + DA SA FC DSAP SSAP (5) + 6 standard diag bytes = offset 15: alarm block.
  ASSERT_GE(diag.size(), 15U + 5U + 2U);
  EXPECT_EQ(diag[15], 0x05);         // header: device-related, length 5 incl. header
                                     // ([IEC 61158-6-3 DPV1 alarms])
  EXPECT_EQ(diag[16], 0x02);         // Alarm_Type process
  EXPECT_EQ(diag[17], 0x00);         // slot 0
  EXPECT_EQ(diag[18] & 0x03, 0x01);  // specifier: appears
  EXPECT_EQ(diag[19], 0x99);         // user data
  const std::uint8_t spec = diag[18];
  Bytes ack = master.request(5, kSapC1, kSapC1, {0x5C, 0x00, 0x02, spec});
  // [IEC 61158-6-3 MSAC_C1 polling] poll
  if (ack == Bytes{0xE5}) ack = master.request(5, kSapC1, kSapC1, {});
  ASSERT_GE(ack.size(), 13U);
  EXPECT_EQ(Bytes(ack.begin() + 9, ack.begin() + 13), (Bytes{0x5C, 0x00, 0x02, spec}));  // echo
  ASSERT_EQ(slave.device().acknowledged_alarms().size(), 1U);
  EXPECT_EQ(slave.device().acknowledged_alarms()[0].type, 2);
}

TEST(GenericDevice, ImageLengthsComeFromTheIdentifiers) {
  // 0x13: general, input, 4 bytes; 0x21: output 2 bytes; 0x50: input 1 word
  // ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]).
  GenericDevice d({{0x13, 0x21, 0x50}});
  EXPECT_EQ(d.input_length(), 6U);
  EXPECT_EQ(d.output_length(), 2U);
  const Bytes out = {0x11, 0x22};
  d.on_outputs(out, TimePoint{});
  std::array<std::uint8_t, 6> in{};
  in.fill(0xEE);
  d.read_inputs(in, TimePoint{});
  EXPECT_EQ(in, (std::array<std::uint8_t, 6>{0x11, 0x22, 0, 0, 0, 0}));
  d.on_outputs_cleared(dp::slave::OutputClear::kLeftDataExchange, TimePoint{});
  d.read_inputs(in, TimePoint{});
  EXPECT_EQ(in[0], 0);
}

TEST(GenericDevice, ConfigCheckIsExactUnlessUserCheck) {
  GenericDevice d({{0x10, 0x20}});
  EXPECT_EQ(d.check_config(Bytes{0x10, 0x20}, false, TimePoint{}), dp::slave::CfgVerdict::kAccept);
  EXPECT_EQ(d.check_config(Bytes{0x20, 0x10}, false, TimePoint{}),
            dp::slave::CfgVerdict::kCfgFault);
  EXPECT_EQ(d.check_config(Bytes{0x20, 0x10}, true, TimePoint{}),
            dp::slave::CfgVerdict::kAccept);  // same lengths
  EXPECT_EQ(d.check_config(Bytes{0x30}, true, TimePoint{}),
            dp::slave::CfgVerdict::kAccept);  // 1 in + 1 out
  EXPECT_EQ(d.check_config(Bytes{0x31}, true, TimePoint{}), dp::slave::CfgVerdict::kCfgFault);
  EXPECT_EQ(d.check_config(Bytes{}, true, TimePoint{}), dp::slave::CfgVerdict::kCfgFault);
}

TEST(GenericDevice, MalformedIdentifiersAreRejectedAtConstruction) {
  EXPECT_THROW(GenericDevice({{0x40}}), std::system_error);  // special: 1 input-length byte missing
  EXPECT_THROW(GenericDevice(GenericDeviceConfig{Bytes{}}), std::system_error);
}

TEST(GenericDevice, RecordStoreLimits) {
  GenericDevice d({{0x30}});
  dp::slave::AcyclicRequest w;
  w.service = dp::slave::AcyclicService::kWrite;
  const Bytes data = {1, 2, 3};
  w.data = data;
  w.length = 3;
  for (std::size_t i = 0; i < GenericDevice::kMaxRecords; ++i) {
    w.index = static_cast<std::uint8_t>(i);
    EXPECT_EQ(d.on_acyclic(w, TimePoint{}).kind, dp::slave::AcyclicResult::Kind::kData);
  }
  w.index = 100;
  const auto full = d.on_acyclic(w, TimePoint{});
  EXPECT_EQ(full.kind, dp::slave::AcyclicResult::Kind::kError);
  EXPECT_EQ(pdu::to_wire(full.error.error_code_1), 0xC3);  // resource unavailable
  w.index = 0;  // overwrite of an existing record still works
  EXPECT_EQ(d.on_acyclic(w, TimePoint{}).kind, dp::slave::AcyclicResult::Kind::kData);
  // Read returns at most the requested length.
  dp::slave::AcyclicRequest r;
  r.service = dp::slave::AcyclicService::kRead;
  r.index = 0;
  r.length = 2;
  const auto got = d.on_acyclic(r, TimePoint{});
  ASSERT_EQ(got.kind, dp::slave::AcyclicResult::Kind::kData);
  EXPECT_EQ(Bytes(got.data.begin(), got.data.end()), (Bytes{1, 2}));
  // Alarm trigger without an attached slave: state conflict, no crash.
  w.index = GenericDevice::kAlarmTriggerIndex;
  const auto alarm = d.on_acyclic(w, TimePoint{});
  EXPECT_EQ(alarm.kind, dp::slave::AcyclicResult::Kind::kError);
  EXPECT_EQ(pdu::to_wire(alarm.error.error_code_1), 0xB5);
}

}  // namespace
}  // namespace rs4sim::dp::devices
