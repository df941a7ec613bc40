// Our master as F-host for GSD F-devices (gsd/station/gsd_master_slaves.h, docs/profisafe.md
// "Our master as F-host for GSD F-devices"), in-process on the memory link on the manual clock:
// a V1 and a V2 GSD F-device (the project's f_module_v1.gsd and f_module_v2.gsd) beside an RS4
// on one bus. The master writes each F-module's F-parameter block into the Set_Prm, its F-hosts
// reach RUN, the F-data cross both ways, a CRC2 fault passivates (fail-safe values) and only
// ACK_REI reintegrates; the F_WD_Time watchdog is pinned on both sides.
#include "app/runtime/master_service.h"
#include "app/runtime/usage_error.h"
#include "dp/link/memory_bus.h"
#include "rpc/gsd_master_service.h"
#include "tests/app/gsd_master_f_calls.h"
#include "rs4/device/rs4_device.h"

#include <gtest/gtest.h>

#include <sstream>

namespace rs4sim::app {
namespace {

namespace device = rs4::device;
using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

const std::string kV1 = std::string(RS4SIM_GSD_CORPUS) + "/f_module_v1.gsd";
const std::string kV2 = std::string(RS4SIM_GSD_CORPUS) + "/f_module_v2.gsd";

Bytes bytes_of(std::span<const std::uint8_t> s) { return {s.begin(), s.end()}; }
Bytes bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

// RS4 4, the V1 F-device 5 ("PROFIsafe v1.x Module" + a standard telegram) and the V2 F-device
// 6 (its preset F-module) at 1.5 Mbit/s, our master acknowledging only on request.
struct FBus {
  dp::ManualClock clock;
  std::ostringstream out;  // the master's console
  MasterServiceOptions options;
  std::unique_ptr<MasterService> service;
  std::vector<std::unique_ptr<GsdStation>> gsd;  // 5 and 6
  std::unique_ptr<device::Rs4Device> rs4;
  testing::InlineExecutor executor;
  std::unique_ptr<rpc::GsdMasterService> api;
  // Last: the stations outlive the bus.
  std::unique_ptr<dp::link::MemoryBus> bus = std::make_unique<dp::link::MemoryBus>(clock);

  explicit FBus(std::optional<std::uint16_t> v1_dest = std::nullopt) {
    device::Rs4MasterOptions r;
    r.address = 4;
    options.station.slaves.push_back(r);
    options.station.auto_ack_rei = false;
    auto specs = parse_gsd_slaves({"5:" + kV1, "6:" + kV2},
                                  {"5:PROFIsafe v1.x Module", "5:Standard telegram 1, PZD-2/2"},
                                  "1.5M");
    specs[0].f_dest_add = v1_dest;
    options.gsd_slaves = specs;
    service = std::make_unique<MasterService>(options, LinkKind::kMemory, out);
    device::Rs4DeviceConfig c;
    c.switches = device::switches_for(4);
    c.boot_time = 1000ms;
    rs4 = std::make_unique<device::Rs4Device>(c);
    for (auto* s : service->stations()) bus->attach(*s);
    bus->attach(*rs4);
    for (auto& spec : specs) {
      gsd.push_back(std::make_unique<GsdStation>(std::move(spec)));
      bus->attach(*gsd.back());
    }
    service->start(clock.now());
    bus->start();
    rs4->power_on(clock.now());
    api = std::make_unique<rpc::GsdMasterService>(
        executor, service->gsd_slaves(),
        [this]() -> dp::master::Master& { return service->station().master(); });
  }
  gsd::FModuleDevice& device(std::size_t i) { return *gsd[i]->application().f_module(0); }
  v1::GsdMasterFModule view(std::uint32_t address) { return calls().f_module(address); }
  grpc::Status acknowledge(std::uint32_t address, std::uint32_t slot) {
    return calls().acknowledge(address, slot);
  }
  grpc::Status set_f_outputs(std::uint32_t address, std::uint32_t slot, const Bytes& data) {
    return calls().set_f_outputs(address, slot, data);
  }
  testing::GsdMasterFCalls calls() { return {*api}; }
};

// The F-parameter block in the Set_Prm the station received: the vendor's default blocks of the
// issue's two GSD facts, `14 00 00 01 00 01 00 64 78 3E` (V1) and `08 40 00 01 00 01 00 96 BB 95`
// (V2), F_Par_CRC = CRC1 over the defaults [IEC 61784-3-3 CRC1].
TEST(MasterGsdFHost, WritesTheFParameterBlocksAndReachesRunBesideAnRs4) {
  FBus b;
  b.bus->run_for(3s);
  ASSERT_TRUE(b.service->healthy()) << b.out.str();
  const auto block = [&](std::size_t i) {
    const auto user = b.gsd[i]->application().user_prm_data();
    const auto at = b.gsd[i]->spec().setup.f_parameters.at(0).offset;
    return Bytes(user.begin() + static_cast<std::ptrdiff_t>(at),
                 user.begin() + static_cast<std::ptrdiff_t>(at + 10));
  };
  EXPECT_EQ(block(0), (Bytes{0x14, 0x00, 0x00, 0x01, 0x00, 0x01, 0x00, 0x64, 0x78, 0x3E}));
  EXPECT_EQ(block(1), (Bytes{0x08, 0x40, 0x00, 0x01, 0x00, 0x01, 0x00, 0x96, 0xBB, 0x95}));
  const auto v1 = b.view(5), v2 = b.view(6);
  EXPECT_EQ(v1.mode(), "V1");
  EXPECT_EQ(v2.mode(), "V2");
  EXPECT_EQ(v1.f_state(), "run");
  EXPECT_EQ(v2.f_state(), "run");
  EXPECT_EQ(v1.parameters().f_par_crc(), 0x783Eu);
  EXPECT_EQ(v2.parameters().f_par_crc(), 0xBB95u);
  EXPECT_EQ(v1.parameters().f_wd_time_ms(), 100u);
  EXPECT_EQ(v2.parameters().f_wd_time_ms(), 150u);
  EXPECT_EQ(v1.f_data_length(), 4u);  // Cfg C0 87 87: 8 bytes = 4 F-data + 1 + 1 + 2
  EXPECT_EQ(v2.f_data_length(), 8u);  // Cfg C0 8B 8B: 12 bytes = 8 F-data + 1 + 3
  EXPECT_EQ(b.device(0).device().state(), profisafe::FDeviceState::kRun);
  const auto text = b.out.str();
  EXPECT_NE(text.find("GSD slave 5: PROFIsafe V1 slot 0: run"), std::string::npos) << text;
  EXPECT_NE(text.find("GSD slave 6: PROFIsafe V2 slot 0: run"), std::string::npos) << text;
  EXPECT_NE(b.service->describe().find("GSD slave 5, 6 (from their GSDs, PROFIsafe F-host for "
                                       "their F-modules)"),
            std::string::npos)
      << b.service->describe();
  b.service->print_status(b.out, {});
  EXPECT_NE(b.out.str().find(", PROFIsafe slot 0 V2 run"), std::string::npos) << b.out.str();
}

// The station's address switch F_Dest_Add 300 (bus-file "f-dest-add"): the master writes 300
// (01 2C) and a CRC1 over that block, which the device accepts.
TEST(MasterGsdFHost, WritesTheStationsFDestAdd) {
  FBus b(300);
  b.bus->run_for(3s);
  ASSERT_TRUE(b.service->healthy()) << b.out.str();
  const auto user = b.gsd[0]->application().user_prm_data();
  EXPECT_EQ(user[4], 0x01);
  EXPECT_EQ(user[5], 0x2C);
  EXPECT_EQ(b.view(5).parameters().f_dest_add(), 300u);
  EXPECT_NE(b.view(5).parameters().f_par_crc(), 0x783Eu);
}

void data_cross_and_crc2_fault_passivates_until_ack_rei(FBus& b, std::size_t i,
                                                        std::uint32_t address) {
  const std::size_t n = b.device(i).f_data_size();
  const Bytes in(n, 0x5A), out(n, 0xC3), zero(n, 0);
  b.device(i).set_f_inputs(in);
  ASSERT_TRUE(b.set_f_outputs(address, 0, out).ok());
  b.bus->run_for(100ms);
  EXPECT_EQ(bytes_of(b.view(address).f_inputs()), in);
  EXPECT_EQ(bytes_of(b.view(address).f_outputs_sent()), out);
  EXPECT_EQ(bytes_of(b.device(i).f_outputs()), out);
  // One corrupted CRC2 from the device: passivated, fail-safe values both ways.
  b.device(i).device().faults().corrupt_crc2 = 1;
  b.bus->run_for(30ms);
  auto v = b.view(address);
  EXPECT_TRUE(v.passivated());
  EXPECT_EQ(v.last_fault(), "CRC2 error");
  EXPECT_EQ(v.counters().at("crc_errors"), 1u);
  EXPECT_EQ(bytes_of(v.f_inputs()), zero);
  // Healthy again: ACK_REQ, still fail-safe until the operator acknowledges.
  b.bus->run_for(200ms);
  v = b.view(address);
  EXPECT_EQ(v.f_state(), "ack-required");
  EXPECT_TRUE(v.ack_req());
  EXPECT_EQ(bytes_of(v.f_inputs()), zero);
  EXPECT_EQ(bytes_of(v.f_outputs_sent()), zero);
  EXPECT_EQ(bytes_of(b.device(i).f_outputs()), zero);
  EXPECT_FALSE(b.service->healthy());
  ASSERT_TRUE(b.acknowledge(address, 0).ok());
  b.bus->run_for(100ms);
  v = b.view(address);
  EXPECT_EQ(v.f_state(), "run");
  EXPECT_EQ(v.counters().at("reintegrations"), 1u);
  EXPECT_EQ(bytes_of(v.f_inputs()), in);
  EXPECT_EQ(bytes_of(b.device(i).f_outputs()), out);
  EXPECT_TRUE(b.service->healthy()) << b.out.str();
}

TEST(MasterGsdFHost, V1CrcFaultPassivatesAndAckReiReintegrates) {
  FBus b;
  b.bus->run_for(3s);
  ASSERT_TRUE(b.service->healthy()) << b.out.str();
  data_cross_and_crc2_fault_passivates_until_ack_rei(b, 0, 5);
  EXPECT_EQ(b.view(6).counters().at("passivations"), 0u);  // the other F-device is not concerned
  EXPECT_NE(b.out.str().find("GSD slave 5: PROFIsafe V1 slot 0: passivated (CRC2 error)"),
            std::string::npos)
      << b.out.str();
}

TEST(MasterGsdFHost, V2CrcFaultPassivatesAndAckReiReintegrates) {
  FBus b;
  b.bus->run_for(3s);
  ASSERT_TRUE(b.service->healthy()) << b.out.str();
  data_cross_and_crc2_fault_passivates_until_ack_rei(b, 1, 6);
  EXPECT_EQ(b.view(5).counters().at("passivations"), 0u);
}

// [PROFIsafe V1.30 F-Device behaviour]: no valid answer within F_WD_Time (100 ms for the V1
// module) passivates. The station leaves the bus at t0; the PDU in flight went out in the cycle
// at or before t0, the F-host looks once per master cycle, and its watchdog runs on while the
// slave is out of data exchange.
TEST(MasterGsdFHost, WatchdogPassivatesAfterFWdTimeNotBefore) {
  FBus b;
  b.bus->run_for(3s);
  ASSERT_TRUE(b.service->healthy()) << b.out.str();
  const auto cycle = b.options.station.cycle_target;
  b.gsd[0]->set_online(false);
  b.bus->run_for(100ms - cycle - 1ms);
  EXPECT_EQ(b.view(5).f_state(), "run");
  EXPECT_NE(b.service->station().master().poll_state(5), dp::master::PollState::kDataExchange);
  b.bus->run_for(2 * cycle + 2ms);
  const auto v = b.view(5);
  EXPECT_TRUE(v.passivated());
  EXPECT_EQ(v.last_fault(), "watchdog F_WD_Time expired");
  EXPECT_EQ(v.counters().at("watchdog_timeouts"), 1u);
  b.gsd[0]->set_online(true);
  b.bus->run_for(1s);
  EXPECT_TRUE(b.view(5).ack_req()) << b.out.str();
}

TEST(MasterGsdFHost, BadRequestsSayWhatIsWrong) {
  FBus b;
  b.bus->run_for(3s);
  ASSERT_TRUE(b.service->healthy()) << b.out.str();
  auto status = b.acknowledge(5, 0);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(status.error_message().find("no ACK_REQ waits for an acknowledgement: the F-host "
                                        "is in state run"),
            std::string::npos)
      << status.error_message();
  status = b.acknowledge(9, 0);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_NE(status.error_message().find("this master's GSD slaves: 5, 6"), std::string::npos);
  status = b.set_f_outputs(5, 1, Bytes{1, 2, 3, 4});
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(status.error_message().find("slot 1 of slave 5 is no PROFIsafe F-module with our "
                                        "F-host (its F-modules: slots 0)"),
            std::string::npos)
      << status.error_message();
  status = b.set_f_outputs(5, 0, Bytes{1, 2, 3});
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(status.error_message().find("3 bytes; the F-module in slot 0 has 4 bytes"),
            std::string::npos)
      << status.error_message();
  v1::SetGsdOutputsRequest raw;
  raw.set_address(5);
  raw.set_slot(0);
  raw.set_data(std::string(8, '\0'));
  v1::Empty empty;
  status = b.api->SetOutputs(nullptr, &raw, &empty);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_NE(status.error_message().find("set its F-data with SetFOutputs"), std::string::npos);
  EXPECT_TRUE(b.service->healthy());  // nothing refused touched the F-hosts
}

// The bus file `rs4sim run --bus` runs on the other end of the line, read by the master: the RS4
// by address, the GSD F-devices with their modules and "f-dest-add".
TEST(MasterGsdFHost, BusFileMixesAnRs4AndGsdFDevices) {
  const auto bus =
      read_master_bus_file(std::string(RS4SIM_GSD_CORPUS) + "/bus_rs4_f_devices.json", "1.5M");
  EXPECT_EQ(bus.rs4s, std::vector<int>{4});
  ASSERT_EQ(bus.gsd.size(), 2u);
  EXPECT_EQ(bus.gsd[0].address, 5);
  EXPECT_EQ(bus.gsd[0].f_dest_add, std::optional<std::uint16_t>(300));
  EXPECT_EQ(bus.gsd[0].modules.at(0).name, "PROFIsafe v1.x Module");
  EXPECT_EQ(bus.gsd[1].address, 6);
  EXPECT_FALSE(bus.gsd[1].f_dest_add);
  gsd::GsdMasterSlaves slaves(bus.gsd);
  EXPECT_EQ(slaves.f_module_count(), 2u);
  EXPECT_EQ(slaves.find(5)->f_modules.at(0).parameters.dest_add, 300);
}

TEST(MasterGsdFHost, GsdFDestAddOptionSetsTheSlavesAddressSwitch) {
  auto specs = parse_gsd_slaves({"5:" + kV1}, {"5:PROFIsafe v1.x Module"}, "1.5M");
  apply_gsd_f_dest_adds(specs, {"5:77"});
  EXPECT_EQ(specs[0].f_dest_add, std::optional<std::uint16_t>(77));
  const auto message = [&](const std::string& value) {
    try {
      apply_gsd_f_dest_adds(specs, {value});
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("6:77"), "--gsd-f-dest-add 6:77: no --gsd-slave 6:FILE given");
  EXPECT_EQ(message("5:x"), "--gsd-f-dest-add 5:x: \"x\" is not a decimal number");
  EXPECT_EQ(message("77"), "--gsd-f-dest-add 77: use ADDRESS:F_DEST_ADD, e.g. 5:300");
}

// --f-wd-time for the GSD F-modules: the F_WD_Time written (and the F-host's watchdog), inside
// the GSD's range 10..10000 (f_module_v1.gsd's ExtUserPrmData 7).
TEST(MasterGsdFHost, FWdTimeOptionSetsTheGsdFModulesWatchdog) {
  auto specs = parse_gsd_slaves({"5:" + kV1}, {"5:PROFIsafe v1.x Module"}, "1.5M");
  apply_gsd_f_wd_time(specs, 500);
  gsd::GsdMasterSlaves slaves(specs);
  EXPECT_EQ(slaves.find(5)->f_modules.at(0).parameters.wd_time_ms, 500);
  EXPECT_EQ(slaves.find(5)->spec.setup.user_prm_data[6], 0x01);  // 500 = 01 F4, big-endian
  EXPECT_EQ(slaves.find(5)->spec.setup.user_prm_data[7], 0xF4);
  try {
    apply_gsd_f_wd_time(specs, 5);
    ADD_FAILURE() << "5 ms accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("f_module_v1.gsd:48: F_WD_Time is 10..10000 for GSD "
                                         "slave 5"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rs4sim::app
