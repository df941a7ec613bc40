// The master side from the shipped GSD (issue 5): Set_Prm/Chk_Cfg bytes, data exchange,
// and the PROFIsafe parameter diagnosis 66 / 72 ([RS4 manual §6.2, §6.3]).
#include "gsd/interp.h"
#include "profisafe/f_parameters.h"
#include "rs4/adapter/rs4_gsd.h"
#include "rs4_fixture.h"
#include "tests/gsd/test_util.h"

namespace rs4sim::rs4::device::testing {
namespace {

TEST(Rs4MasterEntry, SetPrmAndCfgFromTheShippedGsd) {
  Rs4MasterOptions o;
  o.address = 4;
  o.f_wd_time_ms = 150;
  const auto e = rs4_master_entry(o);
  ASSERT_TRUE(e) << e.error().what();
  const auto& s = e.value().slave;
  EXPECT_EQ(s.address, 4);
  EXPECT_EQ(s.prm.ident_number, 0x5234);  // GSD Ident_Number
  EXPECT_TRUE(s.prm.station_status.lock_req);
  EXPECT_TRUE(s.prm.station_status.wd_on);
  ASSERT_TRUE(s.prm.dpv1.has_value());
  EXPECT_TRUE(s.prm.dpv1->dpv1_enable);  // DPV1_Status_1 0x80
  const std::vector<std::uint8_t> user(s.prm.user_data.begin(), s.prm.user_data.end());
  // User_Prm_Data after DPV1_Status_1..3 (docs/gsd.md; [IEC 61784-3-3 F-Parameters]):
  const std::vector<std::uint8_t> expected_head{
      0x0E,        // +0 F-block header: length 14
      0x05,        // +1 structure type
      0x01,        // +2 slot 1
      0x00,        // +3 specifier
      0x14,        // +4 F_Prm_Flag1: SeqNr 0, iPar 0, SIL2 (b2-3 = 01), CRC length 1 (b4-5 = 01)
      0x00,        // +5 F_Prm_Flag2: F_Block_ID 0, F_Par_Version 0 (V1)
      0x00, 0x01,  // +6 F_Source_Add = 1 (GSD default)
      0x01, 0xF8,  // +8 F_Dest_Add = 504 = 500 + address 4 ([RS4 manual §4.5])
      0x00, 0x96,  // +10 F_WD_Time = 150 ms
  };
  ASSERT_EQ(user.size(), expected_head.size() + 2);
  EXPECT_EQ(std::vector<std::uint8_t>(user.begin(), user.begin() + 12), expected_head);
  // +12 F_Par_CRC: CRC1 of those F-parameters (verified algorithm, [IEC 61784-3-3 CRC1]).
  profisafe::FParameters p;
  p.sil = profisafe::Sil::kSil2;
  p.crc_length = profisafe::CrcLength::k2Byte;
  p.source_add = 1;
  p.dest_add = 504;
  p.wd_time_ms = 150;
  const std::uint16_t crc = profisafe::crc1(p);
  EXPECT_EQ(user[12], crc >> 8);
  EXPECT_EQ(user[13], crc & 0xFF);
  EXPECT_EQ(std::vector<std::uint8_t>(s.cfg.begin(), s.cfg.end()),
            (std::vector<std::uint8_t>{0xC0, 0x84, 0x84}));  // 5 bytes out + 5 in, consistent
  EXPECT_EQ(s.input_length, 5U);
  EXPECT_EQ(s.output_length, 5U);
}

TEST(Rs4MasterEntry, OutOfRangeOverrideIsAGsdError) {
  Rs4MasterOptions o;
  o.overrides.push_back({"F_WD_Time", 5});  // GSD range 10..1000
  const auto e = rs4_master_entry(o);
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().code, gsd::GsdError::kOutOfRange);
  EXPECT_THROW(Rs4Segment([&] {
                 auto c = segment_config();
                 c.master = o;
                 return c;
               }()),
               std::invalid_argument);
}

// Issue 5's done-criterion: a master configured from the shipped GSD brings the virtual
// RS4 to data exchange, and the F-host runs (no passivation) over the 5-byte PDUs.
TEST(Rs4MasterOnBus, GsdConfiguredMasterReachesDataExchangeAndFHostRuns) {
  Rs4Segment s(segment_config(17));
  s.power_on();
  ASSERT_TRUE(s.run_until([&] { return s.in_data_exchange(); }, 5s));
  ASSERT_TRUE(s.run_until([&] { return s.fhost().state() == profisafe::FHostState::kRun; }, 1s));
  EXPECT_EQ(s.master().inputs(17).size(), 5U);
  EXPECT_EQ(s.device().adapter().view().f_dest_add, 517);
  const auto before = s.fhost().counters();
  s.run_for(1s);
  EXPECT_EQ(s.fhost().state(), profisafe::FHostState::kRun);
  EXPECT_EQ(s.fhost().counters().crc_errors, before.crc_errors);
  EXPECT_EQ(s.fhost().counters().watchdog_timeouts, before.watchdog_timeouts);
  EXPECT_GE(s.fhost().counters().answers - before.answers, 90U);  // 10 ms cycles
  // During boot the operating-state bit says "not protecting" and OSSD is 0 ([RS4 manual §5.1.1]).
  EXPECT_EQ(s.input_byte() & (kInputOssd | kInputOperatingState), kInputOperatingState);
}

// Bytes 7..11 of the Slave_Diag: status PDU 05 81 00 00 nn ([RS4 manual §6.2, §6.3]).
void expect_profisafe_diag(Rs4Segment& s, std::uint8_t code) {
  s.power_on();
  ASSERT_TRUE(s.run_until(
      [&] {
        const auto st = s.master().slave_status(s.rs4_address());
        return st && st->last_diag.size() >= 11 && st->last_diag[10] == code;
      },
      5s));
  const auto st = s.master().slave_status(s.rs4_address());
  const auto& d = st->last_diag;
  EXPECT_EQ(d[6], 0x05);      // +6 header: length 5 (device-related)
  EXPECT_EQ(d[7], 0x81);      // +7 type: status message
  EXPECT_EQ(d[8], 0x00);      // +8 slot
  EXPECT_EQ(d[9], 0x00);      // +9 specifier
  EXPECT_EQ(d[10], code);     // +10 PROFIsafe error number
  EXPECT_NE(d[0] & 0x40, 0);  // +0 Station_Status_1 bit 6 Prm_Fault ([IEC 61158-6-3 Slave_Diag])
  s.run_for(3s);
  EXPECT_FALSE(s.in_data_exchange());
  EXPECT_TRUE(events_of<dp::master::SlaveEnteredDataExchange>(s).empty());
}

TEST(Rs4MasterOnBus, WrongFDestAddGivesDiagnosis66AndNoDataExchange) {
  auto c = segment_config(4);
  c.master.overrides.push_back({"F_Dest_Add", 505});  // not 500 + 4
  Rs4Segment s(c);
  expect_profisafe_diag(s, 66);
}

TEST(Rs4MasterOnBus, WrongCrc1GivesDiagnosis72AndNoDataExchange) {
  auto c = segment_config(4);
  const auto good = rs4_master_entry(c.master);
  ASSERT_TRUE(good);
  c.master.f_par_crc_override = good.value().f_parameters.par_crc ^ 0x00FF;  // one byte off
  Rs4Segment s(c);
  expect_profisafe_diag(s, 72);
}

}  // namespace
}  // namespace rs4sim::rs4::device::testing

namespace rs4sim::rs4::device::testing {
namespace {

gsd::Device other_gsd() {
  auto d = gsd::parse(gsd::testing::corpus("rs4_other_gsd.gsd"), "rs4_other_gsd.gsd");
  EXPECT_TRUE(d) << d.error().what();
  return std::move(d).value();
}

// `rs4sim run --device rs4 --gsd FILE --link memory`: the RS4 and our master both from the
// project's tests/gsd/corpus/rs4_other_gsd.gsd. The master sends that file's bytes (ident
// 0x7A51, Chk_Cfg B4, the F-block one byte later with slot 0), the RS4 accepts them, and
// PROFIsafe runs over the same 5-byte PDUs; the built-in master is refused by it.
TEST(Rs4MasterOnBus, BothFromAnotherGsdReachDataExchangeAndTheFHostRuns) {
  const gsd::Device d = other_gsd();
  const auto profile = adapter::gsd_profile(d, "", "rs4_other_gsd.gsd");
  ASSERT_TRUE(profile) << profile.error().what();
  auto c = segment_config(4);
  c.device.adapter.gsd = std::make_shared<const adapter::GsdProfile>(profile.value());
  c.master.device = &d;
  const auto e = rs4_master_entry(c.master);
  ASSERT_TRUE(e) << e.error().what();
  EXPECT_EQ(e.value().slave.prm.ident_number, 0x7A51);
  EXPECT_EQ(std::vector<std::uint8_t>(e.value().slave.cfg.begin(), e.value().slave.cfg.end()),
            (std::vector<std::uint8_t>{0xB4}));
  const std::vector<std::uint8_t> user(e.value().slave.prm.user_data.begin(),
                                       e.value().slave.prm.user_data.end());
  ASSERT_EQ(user.size(), 15U);
  EXPECT_EQ(std::vector<std::uint8_t>(user.begin(), user.begin() + 13),
            (std::vector<std::uint8_t>{0x00, 0x0E, 0x05, 0x00, 0x00, 0x14, 0x00, 0x00, 0x01, 0x01,
                                       0xF8, 0x00, 0x96}));
  Rs4Segment s(c);
  s.power_on();
  ASSERT_TRUE(s.run_until([&] { return s.in_data_exchange(); }, 5s));
  ASSERT_TRUE(s.run_until([&] { return s.fhost().state() == profisafe::FHostState::kRun; }, 1s));
  // accepted once (the refusals counted before are the adapter's initialisation, when every
  // Set_Prm is refused [RS4 manual §6.2]), the Cfg never refused
  EXPECT_EQ(s.device().adapter().counters().prm_accepted, 1U);
  EXPECT_EQ(s.device().adapter().counters().cfg_refused, 0U);
  EXPECT_NE(s.device().adapter().led(), adapter::LedState::kSlowBlink);

  auto builtin = segment_config(4);
  builtin.device.adapter.gsd = c.device.adapter.gsd;  // the RS4 from the file, the master not
  Rs4Segment refused(builtin);
  refused.power_on();
  EXPECT_FALSE(refused.run_until([&] { return refused.in_data_exchange(); }, 3s));
  // The built-in master's ident 0x5234 is refused by the slave before the layout is looked at.
  EXPECT_EQ(refused.device().adapter().counters().prm_accepted, 0U);
}

}  // namespace
}  // namespace rs4sim::rs4::device::testing
