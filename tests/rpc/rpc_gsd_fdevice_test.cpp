// GsdStations' F-module calls (gsd_fdevice.proto) end to end: a real gRPC server on loopback in
// front of two GSD F-devices on the simulated bus with our master and its F-hosts
// (app/devices/gsd_segment.h): the project's tests/gsd/corpus/f_module_v1.gsd at address 5 (a
// standard module in slot 0, the drive's "PROFIsafe v1.x Module" in slot 1: 4 F-data bytes,
// F_WD_Time 100 ms, V1) and f_module_v2.gsd at 6 (the F-Link's preset F-module in slot 0: 8
// F-data bytes, F_WD_Time 150 ms, V2). The F_Par_CRC of both are their makers' (0x783E, 0xBB95)
// and our master's Set_Prm carries them; the diagnosis numbers are the standard's 64..71
// [IEC 61784-3-3 F-Parameters].
#include "app/devices/gsd_segment.h"
#include "http_front.h"
#include "rpc/executor.h"
#include "rpc/gsd_service.h"
#include "rpc_calls.h"
#include "rs4sim/v1/gsd.grpc.pb.h"
#include "test_loop.h"

#include <gtest/gtest.h>

#include <memory>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using rpc::unary;
using Stub = v1::GsdStations::Stub;

std::string bytes(const Bytes& b) { return {b.begin(), b.end()}; }

class RpcGsdFDeviceTest : public ::testing::Test, protected rpc::ServedLoop {
 protected:
  void SetUp() override {
    const std::string corpus = RS4SIM_GSD_CORPUS;
    std::vector<GsdStationSpec> specs;
    specs.push_back(load_gsd_station(corpus + "/f_module_v1.gsd",
                                     {"Standard telegram 1, PZD-2/2", "PROFIsafe v1.x Module"}, 5));
    specs.push_back(load_gsd_station(corpus + "/f_module_v2.gsd", {}, 6));
    segment_ = std::make_unique<GsdSegment>(std::move(specs), "12M");
    rpc::GsdServiceContext c{executor_,
                             {segment_->stations()[0].get(), segment_->stations()[1].get()},
                             {},
                             segment_->bus()};
    c.f_hosts = &segment_->f_hosts();
    service_ = std::make_unique<rpc::GsdStationsService>(std::move(c));
    stub_ = serve<v1::GsdStations>(*service_);
    run_for(1s);
  }
  void TearDown() override { stop_serving(); }
  void run_for(dp::Duration d) {
    executor_.run([&] { segment_->run_for(d); });
  }
  v1::GsdFModule module(std::uint32_t address) {
    v1::GsdFModules out;
    EXPECT_TRUE(unary(*stub_, &Stub::GetFModules, rpc::station_request(address), out).ok());
    EXPECT_EQ(out.modules_size(), 1);
    return out.modules_size() == 1 ? out.modules(0) : v1::GsdFModule{};
  }
  grpc::Status inject(std::uint32_t address, std::uint32_t slot, v1::GsdFFault fault,
                      std::uint32_t count = 1, std::uint32_t dest = 0) {
    v1::InjectGsdFFaultRequest in;
    in.set_address(address);
    in.set_slot(slot);
    in.set_fault(fault);
    in.set_count(count);
    in.set_f_dest_add(dest);
    return unary(*stub_, &Stub::InjectFFault, in);
  }
  grpc::Status f_call(grpc::Status (Stub::*rpc)(grpc::ClientContext*, const v1::GsdFModuleRequest&,
                                                v1::Empty*),
                      std::uint32_t address, std::uint32_t slot) {
    v1::GsdFModuleRequest in;
    in.set_address(address);
    in.set_slot(slot);
    return unary(*stub_, rpc, in);
  }
  template <class Request>
  grpc::Status set_data(grpc::Status (Stub::*rpc)(grpc::ClientContext*, const Request&,
                                                  v1::Empty*),
                        std::uint32_t address, std::uint32_t slot, const Bytes& data) {
    Request in;
    in.set_address(address);
    in.set_slot(slot);
    in.set_data(bytes(data));
    return unary(*stub_, rpc, in);
  }

  std::unique_ptr<GsdSegment> segment_;
  std::unique_ptr<rpc::GsdStationsService> service_;
  std::unique_ptr<Stub> stub_;
};

TEST_F(RpcGsdFDeviceTest, BothFDevicesRunWithOurFHostAndCarryTheFData) {
  const auto v1m = module(5);
  EXPECT_EQ(v1m.slot(), 1U);
  EXPECT_EQ(v1m.name(), "PROFIsafe v1.x Module");
  EXPECT_EQ(v1m.mode(), "V1");
  EXPECT_EQ(v1m.state(), "run");
  EXPECT_EQ(v1m.f_data_length(), 4U);
  EXPECT_EQ(v1m.f_wd_time_ms(), 100U);
  EXPECT_EQ(v1m.f_dest_add(), 1U);
  EXPECT_EQ(v1m.diagnosis(), 0U);
  EXPECT_EQ(v1m.host().state(), "run");
  EXPECT_FALSE(v1m.f_outputs_fail_safe());
  const auto v2m = module(6);
  EXPECT_EQ(v2m.mode(), "V2");
  EXPECT_EQ(v2m.f_data_length(), 8U);
  EXPECT_EQ(v2m.f_wd_time_ms(), 150U);
  // V2: every new host PDU flips Toggle_h, the device answers with Toggle_d = Toggle_h.
  EXPECT_EQ(v2m.status() & 0x20U, v2m.host_control() & 0x20U);

  ASSERT_TRUE(set_data(&Stub::SetFInputs, 5, 1, {0x11, 0x22, 0x33, 0x44}).ok());
  ASSERT_TRUE(set_data(&Stub::SetFOutputs, 6, 0, {8, 7, 6, 5, 4, 3, 2, 1}).ok());
  run_for(50ms);
  EXPECT_EQ(module(5).host().f_inputs(), bytes({0x11, 0x22, 0x33, 0x44}));
  EXPECT_EQ(module(5).f_inputs(), bytes({0x11, 0x22, 0x33, 0x44}));
  EXPECT_EQ(module(6).f_outputs(), bytes({8, 7, 6, 5, 4, 3, 2, 1}));
}

TEST_F(RpcGsdFDeviceTest, BadRequestsSayWhatIsWrong) {
  v1::GsdFModules none;
  auto s = unary(*stub_, &Stub::GetFModules, rpc::station_request(9), none);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(s.error_message(), "no GSD station at address 9 (this run's GSD stations: 5, 6)");
  s = set_data(&Stub::SetFInputs, 5, 0, {1, 2});
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(rpc::bad_field_described(s),
            "slot: module \"Standard telegram 1, PZD-2/2\" (slot 0) is no PROFIsafe F-module; the "
            "station's F-modules: slot 1 (\"PROFIsafe v1.x Module\")");
  s = set_data(&Stub::SetFInputs, 5, 2, {1, 2});
  EXPECT_EQ(rpc::bad_field_described(s), "slot: slot 2 outside 0..1 (the station's 2 modules)");
  s = set_data(&Stub::SetFInputs, 5, 1, {1, 2, 3});
  EXPECT_EQ(rpc::bad_field_described(s),
            "data: 3 bytes; F-module \"PROFIsafe v1.x Module\" (slot 1) has 4 F-input bytes");
  s = set_data(&Stub::SetFOutputs, 6, 0, {1});
  EXPECT_EQ(rpc::bad_field_described(s),
            "data: 1 bytes; F-module \"F-Link(PROFIsafe)\" (slot 0) has 8 F-output bytes");
  s = inject(5, 1, static_cast<v1::GsdFFault>(99));
  EXPECT_EQ(rpc::bad_field_described(s),
            "fault: fault kind 99 unknown: a GSD_F_FAULT_* value is required");
  EXPECT_EQ(rpc::bad_field_described(inject(5, 1, v1::GSD_F_FAULT_UNSPECIFIED)),
            "fault: fault kind 0 unknown: a GSD_F_FAULT_* value is required");
  EXPECT_EQ(rpc::bad_field_described(inject(5, 1, v1::GSD_F_FAULT_CORRUPT_CRC2, 0)),
            "count: 0 outside 1..1000000");
  EXPECT_EQ(rpc::bad_field_described(inject(5, 1, v1::GSD_F_FAULT_DELAY)),
            "delay_ms: 0 outside 1..600000");
  EXPECT_EQ(rpc::bad_field_described(inject(5, 1, v1::GSD_F_FAULT_WRONG_F_DEST_ADD, 1, 65535)),
            "f_dest_add: 65535 outside 1..65534");
  EXPECT_EQ(rpc::bad_field_described(inject(5, 1, v1::GSD_F_FAULT_WRONG_F_DEST_ADD, 1, 1)),
            "f_dest_add: 1 is the device's own F_Dest_Add already");
  s = f_call(&Stub::AckFHost, 5, 1);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_EQ(rpc::precondition(s),
            "STATE F-host: no ACK_REQ to acknowledge: the F-host is \"run\"");
  EXPECT_EQ(module(5).host().passivations(), 0U);  // nothing refused reached the device
}

// CORRUPT_CRC2 on the V2 device: the host counts a CRC fault and passivates; healthy again it
// raises ACK_REQ, AckFHost reintegrates.
TEST_F(RpcGsdFDeviceTest, ACorruptCrc2PassivatesTheHostUntilAcknowledged) {
  ASSERT_TRUE(inject(6, 0, v1::GSD_F_FAULT_CORRUPT_CRC2).ok());
  EXPECT_EQ(module(6).pending_corrupt_crc2(), 1U);
  run_for(20ms);
  auto m = module(6);
  EXPECT_EQ(m.pending_corrupt_crc2(), 0U);
  EXPECT_EQ(m.host().crc_errors(), 1U);
  EXPECT_EQ(m.host().passivations(), 1U);
  EXPECT_EQ(m.host().last_fault(), "CRC2 error");
  run_for(500ms);
  EXPECT_EQ(module(6).host().state(), "ack-required");
  ASSERT_TRUE(f_call(&Stub::AckFHost, 6, 0).ok());
  run_for(50ms);
  EXPECT_EQ(module(6).host().state(), "run");
  EXPECT_EQ(module(6).host().reintegrations(), 1U);
}

// WRONG_F_DEST_ADD: the V1 device powers up with switch 2; our master's Set_Prm (F_Dest_Add 1)
// is refused with diagnosis 64, shown by the GSD's own text; ClearFFaults sets it back.
TEST_F(RpcGsdFDeviceTest, AWrongFDestAddGivesDiagnosis64WithTheGsdsText) {
  ASSERT_TRUE(inject(5, 1, v1::GSD_F_FAULT_WRONG_F_DEST_ADD, 1, 2).ok());
  run_for(500ms);
  auto m = module(5);
  EXPECT_EQ(m.f_dest_add(), 2U);
  EXPECT_EQ(m.state(), "parameter-fault");
  EXPECT_EQ(m.diagnosis(), 64U);
  EXPECT_EQ(m.diagnosis_text(), "F add. does not match F_Dest_Add");
  EXPECT_EQ(m.host().state(), "passivated");
  EXPECT_GE(m.host().watchdog_timeouts(), 1U);
  EXPECT_EQ(m.host().last_fault(), "watchdog F_WD_Time expired");
  v1::GsdStation station;
  ASSERT_TRUE(unary(*stub_, &Stub::GetStation, rpc::station_request(5), station).ok());
  EXPECT_EQ(station.diagnosis_texts_size(), 1);
  EXPECT_EQ(station.diagnosis_texts(0), "F add. does not match F_Dest_Add");
  ASSERT_TRUE(f_call(&Stub::ClearFFaults, 5, 1).ok());
  run_for(500ms);
  m = module(5);
  EXPECT_EQ(m.f_dest_add(), 1U);
  EXPECT_EQ(m.diagnosis(), 0U);
  EXPECT_EQ(m.host().state(), "ack-required");
}

TEST_F(RpcGsdFDeviceTest, JsonOverHttpIsTheSameService) {
  rpc::HttpFront h(io_, *server_);
  const auto a = h.call("rs4sim.v1.GsdStations/GetFModules", R"({"address": 6})");
  ASSERT_EQ(a.status, 200u) << a.body;
  EXPECT_NE(a.body.find(R"("mode":"V2")"), std::string::npos) << a.body;
  EXPECT_NE(a.body.find(R"("fWdTimeMs":150)"), std::string::npos) << a.body;
  const auto fault = h.call("rs4sim.v1.GsdStations/InjectFFault",
                            R"({"address": 6, "slot": 0, "fault": "GSD_F_FAULT_DELAY",)"
                            R"( "delayMs": 200})");
  ASSERT_EQ(fault.status, 200u) << fault.body;
  EXPECT_EQ(module(6).held_ms(), 200U);
  run_for(300ms);
  EXPECT_EQ(module(6).host().watchdog_timeouts(), 1U);
  rpc::error_of(h.call("rs4sim.v1.GsdStations/SetFInputs", R"({"address": 6, "slot": 0})"), 400,
                3);
}

}  // namespace
}  // namespace rs4sim::app
