// DPV1 alarms seen by the master ([IEC 61158-6-3 DPV1 alarms]): alarm PDU in the extended
// diagnosis → AlarmReceived → Alarm_Ack, automatic or by the user, Alarm_Mode checks.

#include "master_fixture.h"

#include <gtest/gtest.h>

namespace rs4sim::dp::master::testing {
namespace {

const Bytes kDxDh = {0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x0A, 0x3C, 0x4D, 0x16};
const Bytes kDxDl = {0x68, 0x04, 0x04, 0x68, 0x02, 0x05, 0x08, 0x3C, 0x4B, 0x16};

// Slave_Diag reply of slave 5 (ready, master 2, Ext_Diag) followed by `ext` blocks.
Bytes diag_with(const Bytes& ext) {
  const auto le = static_cast<std::uint8_t>(5 + 6 + ext.size());
  Bytes f;
  f.reserve(6 + le);
  for (std::uint8_t b : {std::uint8_t{0x68}, le, le, std::uint8_t{0x68}}) f.push_back(b);
  for (int b : {0x82, 0x85, 0x08, 0x3E, 0x3C})
    f.push_back(static_cast<std::uint8_t>(b));  // DA SA FC DSAP SSAP
  for (int b : {0x08,                           // Station_Status_1: Ext_Diag
                0x0C,                           // Station_Status_2: WD_On + always-1
                0x00, 0x02,                     // Station_Status_3, Master_Add 2
                0x12, 0x34}) {                  // Ident
    f.push_back(static_cast<std::uint8_t>(b));
  }
  for (std::uint8_t b : ext) f.push_back(b);
  unsigned sum = 0;
  for (std::size_t i = 4; i < f.size(); ++i) sum += f[i];
  f.push_back(static_cast<std::uint8_t>(sum));
  f.push_back(0x16);
  return f;
}

// Diagnostic alarm, slot 0, Seq_Nr 1, "appears" (specifier 0x09) with one data byte.
const Bytes kDiagAlarmSlot0Seq1 = {
    0x05,  // header: device-related block, length 5 incl. header
    0x01,  // Alarm_Type 1 diagnostic (bit 7 = 0: alarm, not status)
    0x00,  // Slot_Number 0
    0x09,  // Alarm_Specifier: Seq_Nr 1 (bits 7..3), Add_Ack 0, appears (01)
    0x5A,  // Diagnostic_User_Data
};

// DX with DH, then the diag fetch answered with `diag`; returns the next request.
Bytes deliver_diag(MasterFixture& f, const Bytes& diag) {
  f.step();  // DX, FCB 0 (5D)
  f.reply(kDxDh);
  f.step();  // Slave_Diag, FCB 1 (7D)
  f.reply(diag);
  return f.step();
}

TEST(MasterAlarm, AlarmIsDeliveredAndAcknowledged) {
  MasterFixture f;
  f.bring_to_dx();
  const Bytes ack = deliver_diag(f, diag_with(kDiagAlarmSlot0Seq1));
  // [IEC 61158-6-3 DPV1 alarms] example: Alarm_Ack for a diagnostic alarm, slot 0, Seq 1, appears.
  EXPECT_EQ(hex(ack), hex(Bytes{0x68, 0x09, 0x09, 0x68,  // SD2, LE 9
                                0x85, 0x82,              // DA 5, SA 2
                                0x5C,                    // SRD low, FCV=1, FCB=0
                                0x33, 0x33,              // DSAP 51, SSAP 51
                                0x5C,                    // Alarm_Ack
                                0x00,                    // slot 0
                                0x01,                    // Alarm_Type 1
                                0x09,                    // Alarm_Specifier
                                0x2F, 0x16}));
  const auto alarms = f.events<AlarmReceived>();
  ASSERT_EQ(alarms.size(), 1U);
  EXPECT_EQ(alarms[0].alarm_type, 1);
  EXPECT_EQ(alarms[0].slot, 0);
  EXPECT_EQ(alarms[0].seq_nr(), 1);
  EXPECT_FALSE(alarms[0].add_ack());
  EXPECT_EQ(alarms[0].data, Bytes{0x5A});
  EXPECT_EQ(f.master.slave_status(5)->alarms_outstanding, 1U);
  // Alarm_Ack.res+ = echo with FC DL ([VPC3+ dp_msac1.c]).
  f.reply({0x68, 0x09, 0x09, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33, 0x5C, 0x00, 0x01, 0x09,
           fcs({0x82, 0x85, 0x08, 0x33, 0x33, 0x5C, 0x00, 0x01, 0x09}), 0x16});
  const auto acked = f.events<AlarmAcknowledged>();
  ASSERT_EQ(acked.size(), 1U);
  EXPECT_FALSE(acked[0].result);
  EXPECT_EQ(f.master.slave_status(5)->alarms_outstanding, 0U);
}

TEST(MasterAlarm, ProcessAlarmFromTheCp5613Example) {
  MasterFixture f;
  f.bring_to_dx();
  // [IEC 61158-6-3 DPV1 alarms] [CP 5613/5614 DP manual p. 187]: `09 02 03 01 50 tt tt tt tt` =
  // process alarm, slot 3, appears, Seq 0.
  deliver_diag(f, diag_with({0x09, 0x02, 0x03, 0x01, 0x50, 0x11, 0x22, 0x33, 0x44}));
  const auto alarms = f.events<AlarmReceived>();
  ASSERT_EQ(alarms.size(), 1U);
  EXPECT_EQ(alarms[0].alarm_type, 2);
  EXPECT_EQ(alarms[0].slot, 3);
  EXPECT_EQ(alarms[0].specifier, 0x01);
  EXPECT_EQ(alarms[0].data, (Bytes{0x50, 0x11, 0x22, 0x33, 0x44}));
}

TEST(MasterAlarm, AcknowledgedAlarmStillInDiagIsNotDeliveredAgain) {
  MasterFixture f;
  f.bring_to_dx();
  deliver_diag(f, diag_with(kDiagAlarmSlot0Seq1));
  f.reply({0xE5});  // ack accepted without echo
  ASSERT_EQ(f.events<AlarmAcknowledged>().size(), 1U);
  f.events<AlarmReceived>();
  // Next cycle: DH again, the same alarm is still in the diag: no new alarm, no new ack.
  const Bytes after = deliver_diag(f, diag_with(kDiagAlarmSlot0Seq1));
  EXPECT_TRUE(f.events<AlarmReceived>().empty());
  EXPECT_EQ(after[4], 0x05) << "next request is the next cycle's DX, not an Alarm_Ack";
}

TEST(MasterAlarm, ManualAcknowledgement) {
  MasterConfig cfg = example_master();
  cfg.auto_alarm_ack = false;
  MasterFixture f(cfg);
  f.bring_to_dx();
  const Bytes next = deliver_diag(f, diag_with(kDiagAlarmSlot0Seq1));
  EXPECT_EQ(next[4], 0x05) << "no automatic Alarm_Ack";
  EXPECT_EQ(f.master.acknowledge_alarm(5, 0, 1, 2),
            make_error_code(MasterError::kAlarmNotOutstanding));
  EXPECT_EQ(f.master.acknowledge_alarm(7, 0, 1, 1), make_error_code(MasterError::kUnknownSlave));
  EXPECT_FALSE(f.master.acknowledge_alarm(5, 0, 1, 1));
  f.reply(kDxDl);
  const Bytes ack = f.step();
  ASSERT_EQ(ack.size(), 15U);
  EXPECT_EQ(hex(Bytes(ack.begin() + 7, ack.begin() + 13)), "33 33 5C 00 01 09");
}

TEST(MasterAlarm, NegativeAckIsReported) {
  MasterFixture f;
  f.bring_to_dx();
  deliver_diag(f, diag_with(kDiagAlarmSlot0Seq1));
  f.reply({0x68, 0x09, 0x09, 0x68, 0x82, 0x85, 0x08, 0x33, 0x33, 0xDC, 0x80, 0xB5,
           0x00,  // Alarm_Ack | 0x80, DPV1, state conflict
           fcs({0x82, 0x85, 0x08, 0x33, 0x33, 0xDC, 0x80, 0xB5, 0x00}), 0x16});
  const auto acked = f.events<AlarmAcknowledged>();
  ASSERT_EQ(acked.size(), 1U);
  EXPECT_EQ(acked[0].result, make_error_code(MasterError::kAlarmAckRejected));
  ASSERT_TRUE(acked[0].negative);
  EXPECT_EQ(pdu::to_wire(acked[0].negative->error_code_1), 0xB5);
}

TEST(MasterAlarm, TypeModeAllowsOneOutstandingAlarmPerType) {
  MasterFixture f;  // Alarm_Mode 0 in the example Set_Prm
  f.bring_to_dx();
  deliver_diag(f, diag_with({0x04, 0x01, 0x00, 0x09,     // diag alarm Seq 1
                             0x04, 0x01, 0x01, 0x11}));  // diag alarm slot 1 Seq 2
  EXPECT_EQ(f.events<AlarmReceived>().size(), 2U);
  const auto faults = f.events<SlaveFault>();
  ASSERT_EQ(faults.size(), 1U);
  EXPECT_EQ(faults[0].reason, make_error_code(MasterError::kAlarmLimitExceeded));
}

TEST(MasterAlarm, SequenceModeAllowsSeveralAndAcksInOrder) {
  MasterConfig cfg = example_master();
  cfg.slaves[0].prm.dpv1->alarm_mode = 1;  // two outstanding alarms in total
  MasterFixture f(cfg);
  f.bring_to_dx();
  const Bytes first = deliver_diag(f, diag_with({0x04, 0x01, 0x00, 0x09, 0x04, 0x01, 0x01, 0x11}));
  EXPECT_TRUE(f.events<SlaveFault>().empty());
  EXPECT_EQ(hex(Bytes(first.begin() + 9, first.begin() + 13)), "5C 00 01 09");
  f.reply({0xE5});
  f.step();
  f.reply(kDxDl);
  const Bytes second = f.step();  // the second ack in the next turn
  EXPECT_EQ(hex(Bytes(second.begin() + 9, second.begin() + 13)), "5C 01 01 11");
}

TEST(MasterAlarm, ExtraAlarmSapUsesSap50) {
  MasterConfig cfg = example_master();
  cfg.slaves[0].extra_alarm_sap = true;
  MasterFixture f(cfg);
  f.bring_to_dx();
  const Bytes ack = deliver_diag(f, diag_with(kDiagAlarmSlot0Seq1));
  EXPECT_EQ(ack[7], 0x32) << "DSAP 50";
  EXPECT_EQ(ack[8], 0x33) << "SSAP 51";
}

TEST(MasterAlarm, MalformedBlockIsReportedNotFatal) {
  MasterFixture f;
  f.bring_to_dx();
  deliver_diag(f, diag_with({0x3F, 0x01}));  // device block claims 63 bytes, 2 present
  EXPECT_EQ(f.events<SlaveFault>().at(0).reason, make_error_code(MasterError::kInvalidResponse));
  EXPECT_EQ(f.master.slave_status(5)->state, PollState::kDataExchange);
}

}  // namespace
}  // namespace rs4sim::dp::master::testing
