// `rs4sim run --bus FILE --link memory --grpc`: one set of services for a whole bus (app/devices/
// bus_file.h, memory_bus_target.h) on a real gRPC server on loopback. The bus file is the
// project's tests/gsd/corpus/bus_rs4_gsd.json: an RS4 at 4 (boot 100 ms), the modular GSD station
// at 5 ("DI 8" 1 input byte, "AI 2" 4, "DO 16 consistent" 2 output bytes) and a generic slave at
// 7, with our master polling all three on the manual clock.
#include "app/devices/bus_file.h"
#include "app/devices/device_registry.h"
#include "rpc/executor.h"
#include "rpc/server.h"
#include "rpc_calls.h"
#include "rs4sim/v1/diagnosis.grpc.pb.h"
#include "rs4sim/v1/gsd.grpc.pb.h"
#include "rs4sim/v1/rs4.grpc.pb.h"
#include "test_loop.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <gtest/gtest.h>

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

#include <algorithm>
#include <memory>
#include <string>
#include <thread>

namespace rs4sim::app {
namespace {

using Bytes = std::vector<std::uint8_t>;

class RpcBusFileTest : public ::testing::Test, protected rpc::TestLoop {
 protected:
  void SetUp() override {
    const DeviceEntry entry = bus_device_entry(
        read_bus_file(std::string(RS4SIM_GSD_CORPUS) + "/" + bus_file(), rate()));
    segment_ = entry.simulate(DeviceOptions{});
    services_ = segment_->services(ServiceContext{executor_, io_, wall_});
    std::vector<grpc::Service*> raw;
    for (const auto& s : services_) raw.push_back(s.get());
    start_loop();
    server_ = std::make_unique<rpc::RpcServer>(rpc::ServerOptions{}, raw);
    const auto channel =
        grpc::CreateChannel(server_->address(), grpc::InsecureChannelCredentials());
    gsd_ = v1::GsdStations::NewStub(channel);
    device_ = v1::Device::NewStub(channel);
    observation_ = v1::Observation::NewStub(channel);
    time_ = v1::SimTime::NewStub(channel);
    diagnostics_ = v1::Diagnostics::NewStub(channel);
  }
  virtual std::string bus_file() const { return "bus_rs4_gsd.json"; }
  virtual std::string rate() const { return "12M"; }
  void TearDown() override {
    server_->shutdown();
    stop_loop();
  }
  std::int64_t advance(std::uint64_t ms) {
    v1::AdvanceRequest in;
    in.set_duration_ms(ms);
    v1::TimeResponse t;
    EXPECT_TRUE(rpc::unary(*time_, &v1::SimTime::Stub::Advance, in, t).ok());
    return t.now_ns();
  }
  v1::GsdStation station(std::uint32_t address) {
    v1::GsdStation out;
    EXPECT_TRUE(
        rpc::unary(*gsd_, &v1::GsdStations::Stub::GetStation, rpc::station_request(address), out)
            .ok());
    return out;
  }
  grpc::Status state(std::uint32_t address, v1::DeviceState* out) {
    return rpc::unary(*observation_, &v1::Observation::Stub::GetState,
                      rpc::station_request(address), *out);
  }

  dp::RealClock wall_;
  std::unique_ptr<SimulatedSegment> segment_;
  ServiceList services_;
  std::unique_ptr<rpc::RpcServer> server_;
  std::unique_ptr<v1::GsdStations::Stub> gsd_;
  std::unique_ptr<v1::Device::Stub> device_;
  std::unique_ptr<v1::Observation::Stub> observation_;
  std::unique_ptr<v1::SimTime::Stub> time_;
  std::unique_ptr<v1::Diagnostics::Stub> diagnostics_;
};

// Each kind of station is reached through its own service, all on the one simulated clock: the
// RS4 through Device/Observation, the GSD station through GsdStations; before SimTime moves the
// clock nothing has happened, after it both are in data exchange with our master.
TEST_F(RpcBusFileTest, EveryStationThroughItsServiceOnTheOneClock) {
  {
    grpc::ClientContext ctx;
    v1::ListGsdStationsResponse list;
    ASSERT_TRUE(gsd_->ListStations(&ctx, v1::Empty{}, &list).ok());
    ASSERT_EQ(list.stations_size(), 1);
    EXPECT_EQ(list.stations(0).address(), 5u);
  }
  {
    grpc::ClientContext ctx;
    v1::ListDevicesResponse list;
    ASSERT_TRUE(device_->ListDevices(&ctx, v1::ListDevicesRequest{}, &list).ok());
    ASSERT_EQ(list.devices_size(), 1);
    EXPECT_EQ(list.devices(0).address(), 4u);
  }
  v1::DeviceState rs4;
  ASSERT_TRUE(state(4, &rs4).ok());
  EXPECT_FALSE(rs4.connected());
  EXPECT_EQ(station(5).dp_state(), "Wait_Prm");
  const std::int64_t t0 = rs4.now_ns();
  EXPECT_EQ(advance(2000), t0 + 2'000'000'000);
  // the GSD station is in data exchange; the RS4's PROFIBUS adapter still initialises (LED
  // steady 2-3 s [RS4 manual §4.4], 2.5 s here) and refuses the master's Set_Prm
  EXPECT_EQ(station(5).dp_state(), "Data_Exch");
  ASSERT_TRUE(state(4, &rs4).ok());
  EXPECT_FALSE(rs4.connected());
  EXPECT_EQ(rs4.now_ns(), t0 + 2'000'000'000);
  EXPECT_EQ(advance(2000), t0 + 4'000'000'000);
  ASSERT_TRUE(state(4, &rs4).ok());
  EXPECT_TRUE(rs4.connected());  // DP data exchange (no F-host on a bus file's bus)
  EXPECT_EQ(station(5).dp_state(), "Data_Exch");
}

// The inputs set through GsdStations go out in the station's next Data_Exchange response, as the
// event stream's telegrams show them on the wire: SD2 68 LE LEr 68, DA = the master (1, the
// lowest free address), SA = 5, FC 08 (response, data low), then the 5 input bytes in slot order
// ("DI 8" then "AI 2") [IEC 61158-4-3 frame formats; IEC 61158-6-3 Data_Exchange].
TEST_F(RpcBusFileTest, InputsReachTheWireInTheNextDataExchange) {
  (void)advance(2000);
  {
    grpc::ClientContext ctx;
    v1::SetGsdInputsRequest in;
    in.set_address(5);
    in.set_slot(1);
    const Bytes ai{0x11, 0x22, 0x33, 0x44};
    in.set_data(std::string(ai.begin(), ai.end()));
    v1::Empty e;
    ASSERT_TRUE(gsd_->SetInputs(&ctx, in, &e).ok());
  }
  grpc::ClientContext ctx;
  v1::StreamEventsRequest req;
  req.add_addresses(5);
  req.set_telegrams(true);
  auto reader = observation_->StreamEvents(&ctx, req);
  // The snapshot's first item says the stream has subscribed: only then may time move, or
  // the telegrams could go by before it (and the read below wait for ever).
  v1::Event e;
  ASSERT_TRUE(reader->Read(&e));
  ASSERT_TRUE(e.has_state()) << "the snapshot comes first";
  EXPECT_EQ(e.state().previous(), "");
  std::thread mover([this] { (void)advance(50); });
  const Bytes expected{0x68, 0x08, 0x08, 0x68, 0x01, 0x05, 0x08, 0x00, 0x11, 0x22, 0x33, 0x44};
  bool seen = false;
  while (!seen && reader->Read(&e)) {
    if (!e.has_telegram() || e.telegram().direction() != v1::DIRECTION_FROM_STATION) continue;
    const std::string& w = e.telegram().frame();
    seen = w.size() >= expected.size() &&
           Bytes(w.begin(), w.begin() + static_cast<long>(expected.size())) == expected;
  }
  mover.join();
  ctx.TryCancel();
  EXPECT_TRUE(seen);
}

// The RS4 calls for the other stations name what they are; an address no station has is
// NOT_FOUND naming the RS4s; GsdStations refuses the RS4's address.
TEST_F(RpcBusFileTest, EachServiceNamesTheStationsItDoesNotServe) {
  v1::DeviceState out;
  const auto gsd = state(5, &out);
  EXPECT_EQ(gsd.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_EQ(gsd.error_message(),
            "address 5: a GSD station (rs4sim.v1.GsdStations), not an RS4 (RS4s: 4)");
  const auto generic = state(7, &out);
  EXPECT_EQ(generic.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_EQ(generic.error_message(),
            "address 7: a generic slave (--ident/--cfg: no API of its own), not an RS4 (RS4s: 4)");
  const auto none = state(9, &out);
  EXPECT_EQ(none.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(none.error_message(), "no RS4 at station 9 (stations: 4)");
  v1::GsdStation s;
  const auto rs4 =
      rpc::unary(*gsd_, &v1::GsdStations::Stub::GetStation, rpc::station_request(4), s);
  EXPECT_EQ(rs4.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_NE(rs4.error_message().find("5"), std::string::npos) << rs4.error_message();
}

// tests/gsd/corpus/bus_rs4_gateway.json: the RS4 at 4 and, at 5, tests/gsd/corpus/gateway_asi.gse
// (DPV1_Slave = 1, Ident_Number 0x0B4E, Max_Diag_Data_Len 32, 1.5M_supp its fastest rate) with
// "Digital 4 byte in/out" in slot 0 and "Analog 2 words in" in slot 1.
class RpcMixedDiagnosisTest : public RpcBusFileTest {
 protected:
  std::string bus_file() const override { return "bus_rs4_gateway.json"; }
  std::string rate() const override { return "1.5M"; }  // the gateway's fastest
  grpc::Status diagnosis(std::uint32_t address, v1::DiagnosisView& out) {
    return rpc::unary(*diagnostics_, &v1::Diagnostics::Stub::GetDiagnosis,
                      rpc::station_request(address), out);
  }
};

// One Diagnostics service answers for each address of the run: the GSD station with its GSD's
// texts for the blocks set through GsdStations.SetDiagnosis, the RS4 with its own ident and no
// GSD text. The blocks, by hand [IEC 61158-6-3 Slave_Diag]: 06 81 01 01 02 05, the
// device-related status PDU of type 0x81 (bits after the header: 8 set, X_Unit_Diag_Bit(8) of
// UnitDiagType 129 "peripheral fault"; 16 set "AS-i voltage too low"; 18 clear "gateway not in
// protected mode"; 24-27 = 2 "double address": the file's texts);
// 42 02, the identifier block marking slot 1; 81 41 27, module 1's input channel 1, error 7.
TEST_F(RpcMixedDiagnosisTest, EachStationInItsOwnWords) {
  (void)advance(4000);
  v1::DiagnosisView gsd;
  ASSERT_TRUE(diagnosis(5, gsd).ok());
  EXPECT_EQ(gsd.address(), 5U);
  EXPECT_EQ(gsd.ident_number(), 0x0B4EU);
  EXPECT_EQ(gsd.master_address(), 1U);  // our master, the lowest free address
  EXPECT_EQ(gsd.blocks_size(), 0);
  EXPECT_TRUE(gsd.texts().empty());
  v1::SetGsdDiagnosisRequest set;
  set.set_address(5);
  set.set_ext_diag(true);
  const Bytes blocks{0x06, 0x81, 0x01, 0x01, 0x02, 0x05, 0x42, 0x02, 0x81, 0x41, 0x27};
  set.set_blocks(std::string(blocks.begin(), blocks.end()));
  const auto s = rpc::unary(*gsd_, &v1::GsdStations::Stub::SetDiagnosis, set);
  ASSERT_TRUE(s.ok()) << s.error_message();
  ASSERT_TRUE(diagnosis(5, gsd).ok());
  EXPECT_EQ(gsd.raw().substr(6), std::string(blocks.begin(), blocks.end()));
  EXPECT_NE(std::find(gsd.station_status().begin(), gsd.station_status().end(), "Ext_Diag"),
            gsd.station_status().end());
  ASSERT_EQ(gsd.blocks_size(), 3) << gsd.error();
  EXPECT_EQ(std::vector<std::string>(gsd.texts().begin(), gsd.texts().end()),
            (std::vector<std::string>{
                "peripheral fault", "AS-i voltage too low", "gateway not in protected mode",
                "double address",
                "slot 1 \"Analog 2 words in\" reports diagnosis",
                "slot 1 \"Analog 2 words in\" channel 1 input: error 7 (upper limit exceeded)"}));
  v1::DiagnosisView rs4;
  ASSERT_TRUE(diagnosis(4, rs4).ok());
  EXPECT_EQ(rs4.address(), 4U);
  EXPECT_EQ(rs4.ident_number(), 0x5234U);  // the built-in GSD gsd/files/RSIM5234.gsd
  EXPECT_TRUE(rs4.texts().empty());
  v1::DiagnosisView none;
  EXPECT_EQ(diagnosis(9, none).error_code(), grpc::StatusCode::NOT_FOUND);
}

// tests/gsd/corpus/bus_rs4_f_devices.json on the simulated bus: the RS4 at 4, the V1 GSD
// F-device at 5 (the drive's "PROFIsafe v1.x Module", address switch F_Dest_Add 300 by the
// file's "f-dest-add") and the V2 one at 6 (the F-Link's preset module, the GSD's F_Dest_Add 1).
// Our master reads the same file, so its F-hosts send 300 to station 5 and both reach run; a
// corrupted CRC2 passivates station 5's F-host until AcknowledgeF, station 6's runs on.
class RpcBusFileFDevicesTest : public RpcBusFileTest {
 protected:
  std::string bus_file() const override { return "bus_rs4_f_devices.json"; }
  v1::GsdFModule f_module(std::uint32_t address) {
    v1::GsdFModules out;
    EXPECT_TRUE(rpc::unary(*gsd_, &v1::GsdStations::Stub::GetFModules,
                           rpc::station_request(address), out)
                    .ok());
    return out.modules_size() == 1 ? out.modules(0) : v1::GsdFModule{};
  }
};

TEST_F(RpcBusFileFDevicesTest, TheFileGivesBothEndsTheFDestAddAndOurFHostsRun) {
  (void)advance(2000);
  const auto v1m = f_module(5);
  EXPECT_EQ(v1m.mode(), "V1");
  EXPECT_EQ(v1m.f_dest_add(), 300U);
  EXPECT_EQ(v1m.diagnosis(), 0U) << v1m.diagnosis_text();
  EXPECT_EQ(v1m.state(), "run");
  EXPECT_EQ(v1m.host().state(), "run");
  const auto v2m = f_module(6);
  EXPECT_EQ(v2m.mode(), "V2");
  EXPECT_EQ(v2m.host().state(), "run");

  v1::InjectGsdFFaultRequest fault;
  fault.set_address(5);
  fault.set_slot(v1m.slot());
  fault.set_fault(v1::GSD_F_FAULT_CORRUPT_CRC2);
  fault.set_count(1);
  ASSERT_TRUE(rpc::unary(*gsd_, &v1::GsdStations::Stub::InjectFFault, fault).ok());
  (void)advance(200);
  EXPECT_EQ(f_module(5).host().state(), "ack-required");
  EXPECT_EQ(f_module(6).host().state(), "run");
  v1::GsdFModuleRequest ack;
  ack.set_address(5);
  ack.set_slot(v1m.slot());
  ASSERT_TRUE(rpc::unary(*gsd_, &v1::GsdStations::Stub::AcknowledgeF, ack).ok());
  (void)advance(200);
  EXPECT_EQ(f_module(5).host().state(), "run");
}

}  // namespace
}  // namespace rs4sim::app
