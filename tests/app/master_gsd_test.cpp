// `rs4sim master` with a GSD slave beside an RS4 (app/runtime/master_gsd.h), in-process on the
// memory link on the manual clock: the master configures the GSD station from the same GSD
// (Set_Prm with the GSD's default User_Prm_Data [IEC 61158-6-3 Set_Prm], Chk_Cfg from the modules
// [IEC 61158-6-3 Chk_Cfg/Get_Cfg]), both reach data exchange on one bus, and the I/O set on each
// side arrives at the other. The GSD is the project's tests/gsd/corpus/modular_dpv1.gsd.
#include "app/runtime/master_service.h"
#include "app/runtime/usage_error.h"
#include "dp/link/memory_bus.h"
#include "rpc/gsd_master_service.h"
#include "rpc/gsd_service.h"
#include "rs4/device/rs4_device.h"

#include <gtest/gtest.h>

#include <sstream>

namespace rs4sim::app {
namespace {

namespace device = rs4::device;
using Bytes = std::vector<std::uint8_t>;
using rpc::GsdMasterService;
using rpc::GsdServiceContext;
using rpc::GsdStationsService;

const std::string kGsd = std::string(RS4SIM_GSD_CORPUS) + "/modular_dpv1.gsd";

Bytes bytes_of(std::span<const std::uint8_t> s) { return {s.begin(), s.end()}; }

// RS4 4 and the GSD station 5 ("DI 8": 1 input byte, "AI 2": 4, "DO 16 consistent": 2 output
// bytes) on one memory bus with our master at 12 Mbit/s (the GSD's rates: 9.6k, 1.5M, 12M).
struct MixedBus {
  dp::ManualClock clock;
  std::ostringstream out;
  MasterServiceOptions options;
  std::unique_ptr<MasterService> service;
  std::unique_ptr<device::Rs4Device> rs4;
  std::unique_ptr<GsdStation> gsd;
  std::unique_ptr<dp::link::MemoryBus> bus;

  MixedBus() {
    device::Rs4MasterOptions r;
    r.address = 4;
    options.station.slaves.push_back(r);
    options.station.bus = dp::master::BusParameters::defaults_for(dp::BaudRate::k12M);
    auto spec = parse_gsd_slaves({"5:" + kGsd}, {"5:DI 8", "5:AI 2", "5:DO 16 consistent"}, "12M");
    options.gsd_slaves = spec;
    service = std::make_unique<MasterService>(options, LinkKind::kMemory, out);
    device::Rs4DeviceConfig c;
    c.switches = device::switches_for(4);
    c.boot_time = std::chrono::milliseconds(1000);
    rs4 = std::make_unique<device::Rs4Device>(c);
    gsd = std::make_unique<GsdStation>(std::move(spec.front()));
    bus = std::make_unique<dp::link::MemoryBus>(clock);
    for (auto* s : service->stations()) bus->attach(*s);
    bus->attach(*rs4);
    bus->attach(*gsd);
    service->start(clock.now());
    bus->start();
    rs4->power_on(clock.now());
  }
  dp::master::Master& master() { return service->station().master(); }
};

TEST(MasterGsd, ConfiguresTheStationFromItsGsdAndReachesDataExchangeBesideAnRs4) {
  MixedBus b;
  b.bus->run_for(std::chrono::seconds(3));
  EXPECT_EQ(b.gsd->slave().state(), dp::slave::State::kDataExch) << b.out.str();
  EXPECT_EQ(b.master().poll_state(5), dp::master::PollState::kDataExchange);
  EXPECT_TRUE(b.gsd->application().prm_fault().empty()) << b.gsd->application().prm_fault();
  // User_Prm_Data worked out by hand from the file: Ext_User_Prm_Data_Const(0) 80 00 00 01,
  // byte 3 with "Diagnosis" Bit(2) = 1 and "Mode" BitArea(4-6) = 3 → 0x35; then module "AI 2"'s
  // 4 bytes: Const AA, "Filter time" Unsigned16 300 = 01 2C, "Offset" Signed8 -5 = FB.
  EXPECT_EQ(bytes_of(b.gsd->application().user_prm_data()),
            (Bytes{0x80, 0x00, 0x00, 0x35, 0xAA, 0x01, 0x2C, 0xFB}));
  // The RS4 on the same bus: data exchange with its F-host running.
  EXPECT_TRUE(b.service->healthy()) << b.out.str();
  const auto text = b.out.str();
  EXPECT_NE(text.find("GSD slave 5: " + kGsd + ", ident 0xB756, modules \"DI 8\", \"AI 2\", "
                      "\"DO 16 consistent\", Chk_Cfg 10 51 a1"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("GSD slave 5: DP data exchange"), std::string::npos) << text;
  b.service->print_status(b.out, {});
  EXPECT_NE(b.out.str().find("GSD slave 5: end: DP DataExchange"), std::string::npos);
}

TEST(MasterGsd, InputsArriveAtTheMasterAndOutputsAtTheStation) {
  MixedBus b;
  b.bus->run_for(std::chrono::seconds(3));  // the RS4 in data exchange with PROFIsafe running
  ASSERT_EQ(b.master().poll_state(5), dp::master::PollState::kDataExchange) << b.out.str();
  ASSERT_FALSE(b.gsd->application().set_inputs(0, Bytes{0x5A}));
  ASSERT_FALSE(b.gsd->application().set_inputs(1, Bytes{0x11, 0x22, 0x33, 0x44}));
  auto& gsd = b.service->gsd_slaves();
  EXPECT_FALSE(gsd.set_outputs(b.master(), 5, 2, Bytes{0xBE, 0xEF}));
  b.bus->run_for(std::chrono::milliseconds(50));
  EXPECT_EQ(bytes_of(b.master().inputs(5)), (Bytes{0x5A, 0x11, 0x22, 0x33, 0x44}));
  EXPECT_EQ(bytes_of(b.gsd->application().outputs()), (Bytes{0xBE, 0xEF}));
  EXPECT_NE(b.out.str().find("GSD slave 5: inputs 5a 11 22 33 44"), std::string::npos)
      << b.out.str();
  // The RS4's process data is untouched by the GSD slave's.
  EXPECT_TRUE(b.service->healthy());

  EXPECT_EQ(gsd.set_outputs(b.master(), 5, 2, Bytes{0x01}), std::errc::invalid_argument);
  EXPECT_EQ(gsd.set_outputs(b.master(), 5, 3, Bytes{0x01, 0x02}), std::errc::result_out_of_range);
  EXPECT_EQ(gsd.set_outputs(b.master(), 4, 0, Bytes{0x01}),
            std::errc::no_such_device_or_address);  // the RS4 is no GSD slave
  b.bus->run_for(std::chrono::milliseconds(50));
  EXPECT_EQ(bytes_of(b.gsd->application().outputs()), (Bytes{0xBE, 0xEF}));  // refused: unchanged
}

// The services' calls without a server: the loop is the test's own thread.
class InlineExecutor final : public rpc::Executor {
 public:
  void run(const std::function<void()>& f) override { f(); }
};

// gateway_asi.gse's Unit_Diag texts (bits 16, 17, Not_Bit 18, area 24-27, counted after the
// device-related block's header) for a diagnosis raised at the station: the station's
// GsdStations and the master's GsdMaster and report show the same texts.
TEST(MasterGsd, UnitDiagTextsOnBothSides) {
  dp::ManualClock clock;
  std::ostringstream out;
  MasterServiceOptions o;
  o.station.bus = dp::master::BusParameters::defaults_for(dp::BaudRate::k1M5);
  const std::string gse = std::string(RS4SIM_GSD_CORPUS) + "/gateway_asi.gse";
  auto specs = parse_gsd_slaves({"6:" + gse}, {"6:Status 1 byte"}, "1.5M");
  o.gsd_slaves = specs;
  MasterService service(o, LinkKind::kMemory, out);
  GsdStation station(std::move(specs.front()));
  dp::link::MemoryBus bus(clock);
  for (auto* s : service.stations()) bus.attach(*s);
  bus.attach(station);
  service.start(clock.now());
  bus.start();
  bus.run_for(std::chrono::milliseconds(500));
  ASSERT_EQ(service.station().master().poll_state(6), dp::master::PollState::kDataExchange)
      << out.str();

  // Device-related block, 5 bytes with the header: bit 17 set, bit 18 clear, bits 24..27 = 1.
  ASSERT_FALSE(station.application().set_diagnosis(Bytes{0x05, 0x00, 0x00, 0x02, 0x01}, true));
  bus.run_for(std::chrono::milliseconds(100));
  const std::string texts = "AS-i configuration error; gateway not in protected mode; earth fault";
  EXPECT_NE(out.str().find("GSD slave 6: diagnosis " + texts + " (05 00 00 02 01)"),
            std::string::npos)
      << out.str();

  InlineExecutor executor;
  GsdMasterService master_api(executor, service.gsd_slaves(),
                              [&]() -> dp::master::Master& { return service.station().master(); });
  v1::StationRequest request;
  request.set_address(6);
  v1::GsdMasterSlave slave;
  ASSERT_TRUE(master_api.GetSlave(nullptr, &request, &slave).ok());
  const std::vector<std::string> expected{"AS-i configuration error",
                                          "gateway not in protected mode", "earth fault"};
  EXPECT_EQ(std::vector<std::string>(slave.diagnosis_texts().begin(),
                                     slave.diagnosis_texts().end()),
            expected);
  GsdStationsService station_api(GsdServiceContext{executor, {&station}});
  v1::GsdStation listed;
  ASSERT_TRUE(station_api.GetStation(nullptr, &request, &listed).ok());
  EXPECT_EQ(std::vector<std::string>(listed.diagnosis_texts().begin(),
                                     listed.diagnosis_texts().end()),
            expected);

  // Cleared: the Not_Bit's text alone (bit 18 clear in a block that holds it) is gone too
  // with a block that sets bit 18.
  ASSERT_FALSE(station.application().set_diagnosis(Bytes{0x04, 0x00, 0x00, 0x04}, true));
  bus.run_for(std::chrono::milliseconds(100));
  EXPECT_NE(out.str().find("GSD slave 6: diagnosis cleared (04 00 00 04)"), std::string::npos)
      << out.str();
}

TEST(MasterGsd, BadOptionsNameWhatIsWrong) {
  const auto message = [](const std::vector<std::string>& slaves,
                          const std::vector<std::string>& modules) {
    try {
      (void)parse_gsd_slaves(slaves, modules, "12M");
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message({"5:" + kGsd}, {"5:DI 9"}),
            kGsd + ": no module \"DI 9\" in the GSD (modules: \"DI 8\", \"AI 2\", \"DO 16 consistent\")");
  EXPECT_EQ(message({"5:" + kGsd, "5:" + kGsd}, {}),
            "--gsd-slave 5:" + kGsd + ": address 5 is already the GSD slave of " + kGsd);
  EXPECT_EQ(message({"5:" + kGsd}, {"6:DI 8"}), "--module 6:DI 8: no --gsd-slave 6:FILE given");
  EXPECT_EQ(message({"126:" + kGsd}, {}),
            "--gsd-slave 126:" + kGsd +
                ": address 126 is outside 0..125 ([IEC 61158-4-3 addresses, SAPs])");
  EXPECT_EQ(message({kGsd}, {}), "--gsd-slave " + kGsd + ": use ADDRESS:FILE, e.g. 5:X.gsd");
  EXPECT_EQ(message({"5:"}, {}), "--gsd-slave 5:: use ADDRESS:FILE, e.g. 5:X.gsd");
  // A module name may hold ':' and ',': only the first ':' ends the address.
  EXPECT_EQ(message({"5:" + kGsd}, {"5:DI 8: a, b"}),
            kGsd + ": no module \"DI 8: a, b\" in the GSD (modules: \"DI 8\", \"AI 2\", \"DO 16 consistent\")");
  // The rates the GSD declares: 9.6k, 1.5M and 12M, listed as --baud takes them.
  try {
    (void)parse_gsd_slaves({"5:" + kGsd}, {"5:DI 8"}, "3M");
    ADD_FAILURE() << "3M accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("does not support 3M bit/s (its GSD: 9.6k, 1.5M, 12M)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rs4sim::app
