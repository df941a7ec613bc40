// Any DP slave from its GSD (gsd/station/gsd_station.h): our master configured from the same GSD
// reaches data exchange with it on the in-memory bus (manual clock), I/O set per module arrives
// at the master and the master's outputs at the station; a Set_Prm outside the GSD's ranges is
// refused with Prm_Fault, a Chk_Cfg of other modules with Cfg_Fault ([IEC 61158-6-3 Set_Prm,
// Chk_Cfg/Get_Cfg, Slave_Diag]). The GSD files are the project's own test files (tests/gsd/corpus).
#include "app/devices/gsd_segment.h"
#include "app/devices/gsd_station_file.h"
#include "app/runtime/usage_error.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

const std::string kCorpus = RS4SIM_GSD_CORPUS;
const std::string kGateway = kCorpus + "/gateway_asi.gse";
const std::string kStarter = kCorpus + "/depart_moteur_fr.gsf";

GsdStationSpec gateway(int address) {
  return load_gsd_station(kGateway, {"Digital 4 byte in/out", "Analog 2 words in"}, address);
}

// Our master and one GSD station on a memory bus, the master's entry as given.
struct Rig {
  dp::ManualClock clock;
  dp::link::MemoryBus bus{clock};
  std::unique_ptr<dp::master::Master> master;
  std::unique_ptr<GsdStation> station;

  Rig(GsdStationSpec spec, dp::master::SlaveEntry entry) {
    dp::master::MasterConfig m;
    m.address = 1;
    m.bus = dp::master::BusParameters::defaults_for(dp::BaudRate::k1M5);
    m.slaves = {std::move(entry)};
    master = std::make_unique<dp::master::Master>(m);
    station = std::make_unique<GsdStation>(std::move(spec));
    bus.attach(*master);
    bus.attach(*station);
    bus.start();
  }
  void run(dp::Duration d) {
    std::vector<dp::master::MasterEvent> events;
    bus.run_until([] { return false; }, clock.now() + d, [&] { master->take_events(events); });
  }
};

// The slot list of gsd::place_modules for the station and our master alike: the file's three
// presets ahead of the user's modules (its header comment gives the bytes worked out by hand).
TEST(GsdStation, PresetModulesLeadTheStationAndOurMastersChkCfg) {
  GsdStationSpec spec = load_gsd_station(kCorpus + "/preset_im153_style.gsd", {"DI 16", "DO 8"}, 5);
  const Bytes cfg{0x04, 0x00, 0x00, 0xAD, 0xC4, 0x04, 0x00, 0x00, 0x8B, 0x41,
                  0x04, 0x00, 0x00, 0x8F, 0xC0, 0x11, 0x20};
  EXPECT_EQ(spec.setup.cfg, cfg);
  ASSERT_EQ(spec.modules.size(), 5U);
  EXPECT_TRUE(spec.modules[2].preset);
  EXPECT_FALSE(spec.modules[3].preset);
  EXPECT_EQ(spec.modules[3].input_offset, 0U);  // the presets carry no I/O
  const auto entry = gsd_master_entry(spec, 100ms);
  EXPECT_EQ(Bytes(entry.cfg.begin(), entry.cfg.end()), cfg);
  std::vector<GsdStationSpec> specs;
  specs.push_back(std::move(spec));
  GsdSegment segment(std::move(specs), "1.5M");
  segment.run_for(500ms);
  EXPECT_EQ(segment.in_data_exchange(), 1U);
  EXPECT_NE(segment.stations().front()->describe().find(
                "modules \"Config for Slot1\" (preset), \"Config for Slot2\" (preset)"),
            std::string::npos)
      << segment.stations().front()->describe();
}

TEST(GsdStation, MasterFromTheSameGsdReachesDataExchangeAndIoFlowsPerModule) {
  std::vector<GsdStationSpec> specs;
  specs.push_back(gateway(5));
  GsdSegment segment(std::move(specs), "1.5M");
  EXPECT_EQ(segment.master_address(), 1);
  segment.run_for(500ms);
  ASSERT_EQ(segment.in_data_exchange(), 1U);
  GsdStation& s = *segment.stations().front();
  EXPECT_EQ(s.slave().state(), dp::slave::State::kDataExch);
  // Set_Prm as the GSD lays it out: 80 00 00 | mode 0 | filter 2 | profile 7 << 4.
  EXPECT_EQ(Bytes(s.application().user_prm_data().begin(), s.application().user_prm_data().end()),
            (Bytes{0x80, 0x00, 0x00, 0x00, 0x02, 0x70}));
  // Module 0 "Digital 4 byte in/out": 4 in, 4 out; module 1 "Analog 2 words in": 4 in.
  EXPECT_FALSE(s.application().set_inputs(1, Bytes{0x12, 0x34, 0x56, 0x78}));
  EXPECT_FALSE(s.application().set_inputs(0, Bytes{0xA1, 0xA2, 0xA3, 0xA4}));
  EXPECT_EQ(s.application().set_inputs(1, Bytes{0x01}), std::errc::invalid_argument);
  EXPECT_EQ(s.application().set_inputs(2, Bytes{}), std::errc::invalid_argument);
  EXPECT_FALSE(segment.master().set_outputs(5, Bytes{0x0F, 0x0E, 0x0D, 0x0C}));
  segment.run_for(50ms);
  const auto in = segment.master().inputs(5);
  EXPECT_EQ(Bytes(in.begin(), in.end()),
            (Bytes{0xA1, 0xA2, 0xA3, 0xA4, 0x12, 0x34, 0x56, 0x78}));
  const auto out = s.application().outputs();
  EXPECT_EQ(Bytes(out.begin(), out.end()), (Bytes{0x0F, 0x0E, 0x0D, 0x0C}));
  EXPECT_TRUE(s.application().prm_fault().empty());
}

TEST(GsdStation, SetPrmOutsideTheGsdRangeIsRefusedWithPrmFault) {
  GsdStationSpec spec = gateway(6);
  auto entry = gsd_master_entry(spec, 100ms);
  // SetPrm::user_data starts after DPV1_Status_1..3: index 1 = User_Prm_Data byte 4, the
  // input filter; 3 ms is not in its list 1, 2, 5, 10.
  ASSERT_EQ(entry.prm.user_data.size(), 3U);
  entry.prm.user_data[1] = 3;
  Rig rig(std::move(spec), std::move(entry));
  rig.run(500ms);
  EXPECT_EQ(rig.station->slave().state(), dp::slave::State::kWaitPrm);
  EXPECT_EQ(rig.station->application().prm_fault(),
            "byte 4: Input filter (ms) = 3 is not allowed (1, 2, 5, 10)");
  const auto status = rig.master->slave_status(6);
  ASSERT_TRUE(status);
  EXPECT_NE(status->state, dp::master::PollState::kDataExchange);
  ASSERT_GE(status->last_diag.size(), 6U);
  EXPECT_NE(status->last_diag[0] & 0x40, 0) << "Station_Status_1 Prm_Fault";
}

TEST(GsdStation, ChkCfgOfOtherModulesIsRefusedWithCfgFault) {
  GsdStationSpec spec = gateway(7);
  auto entry = gsd_master_entry(spec, 100ms);
  entry.cfg = {0x33, 0x10};  // "Status 1 byte" in slot 2 instead of the analog module
  entry.input_length = 5;
  Rig rig(std::move(spec), std::move(entry));
  rig.run(500ms);
  EXPECT_NE(rig.station->slave().state(), dp::slave::State::kDataExch);
  const auto status = rig.master->slave_status(7);
  ASSERT_TRUE(status);
  ASSERT_GE(status->last_diag.size(), 6U);
  EXPECT_NE(status->last_diag[0] & 0x04, 0) << "Station_Status_1 Cfg_Fault";
}

TEST(GsdStation, DeclaredCapabilitiesReachTheSlave) {
  GsdStation dpv0(load_gsd_station(kStarter, {}, 9));
  EXPECT_EQ(dpv0.spec().setup.ident_number, 0x09C1);
  EXPECT_FALSE(dpv0.spec().setup.dpv1);
  EXPECT_EQ(dpv0.spec().modules.size(), 1U);  // the compact station's one module, implicit
  EXPECT_EQ(dpv0.spec().modules[0].input_len, 2U);
  EXPECT_EQ(gsd_max_tsdr(dpv0.spec(), "1.5M"), 25);
  EXPECT_EQ(gsd_max_tsdr(dpv0.spec(), "12M"), 800);
  EXPECT_NO_THROW(check_gsd_baud(dpv0.spec(), "187.5k"));
  EXPECT_THROW(check_gsd_baud(dpv0.spec(), "19.2k"), UsageError);
  EXPECT_NE(dpv0.describe().find("ident 0x09C1"), std::string::npos) << dpv0.describe();
}

TEST(GsdSegmentTiming, MasterWaitsForTheSlowestMaxTsdr) {
  // [IEC 61158-4-3 bus parameters, timing] at 1.5 Mbit/s: TSL 300, max TSDR 150.
  auto bus = dp::master::BusParameters::defaults_for(dp::BaudRate::k1M5);
  ASSERT_EQ(bus.tsl, 300U);
  ASSERT_EQ(bus.max_tsdr, 150U);
  fit_max_tsdr(bus, 150);  // not above: unchanged
  EXPECT_EQ(bus.tsl, 300U);
  fit_max_tsdr(bus, 400);
  EXPECT_EQ(bus.max_tsdr, 400U);
  EXPECT_EQ(bus.tsl, 550U);  // the table's 150 Tbit margin kept
  EXPECT_GE(bus.tid2, 400U);
  fit_max_tsdr(bus, 200);
  EXPECT_EQ(bus.max_tsdr, 400U);
  EXPECT_THROW(fit_max_tsdr(bus, 1024), UsageError);
  EXPECT_EQ(free_master_address({1, 2, 4}), 3);
  EXPECT_EQ(free_master_address({5}), 1);
}

TEST(GsdStation, BadInputNamesTheFileLineOrTheModules) {
  try {
    (void)load_gsd_station(kGateway, {"Digital 4 byte in/out", "Relay 8"}, 5);
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()),
              kGateway + ": no module \"Relay 8\" in the GSD (modules: \"Digital 4 byte in/out\", "
                         "\"Analog 2 words in\", \"Status 1 byte\")");
  }
  try {
    (void)load_gsd_station(kCorpus + "/missing.gsd", {}, 5);
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), kCorpus + "/missing.gsd: cannot read the GSD file: No such file or directory");
  }
  EXPECT_THROW((void)load_gsd_station(kStarter, {}, 126), UsageError);
  std::vector<std::string> warnings;
  (void)load_gsd_station(kGateway, {"Status 1 byte"}, 5, &warnings);
  ASSERT_EQ(warnings.size(), 1U);
  EXPECT_EQ(warnings[0].rfind(kGateway + ":85: 'Unit_Diag_!Bit' is not a GSD keyword", 0), 0U)
      << warnings[0];
}

}  // namespace
}  // namespace rs4sim::app
