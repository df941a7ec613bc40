// The Device calls the scenario tests do not reach, end to end on a real server on loopback
// in front of the simulated segment (docs/rpc.md): the run's device list, power off/on and
// a power cycle with the RS4's boot time [RS4 manual §1], the contour of a known scene and
// ClearScene, the PC adapter's switched-through bit and the Proxy-Request on its removal
// [RS4 manual §7.1, §7.2], an RS4 fault cleared, the address switches taking effect at the
// next power-on with F_Dest_Add = 500 + address [RS4 manual §4.5], bus faults cleared
// [IEC 61158-4-3 FCB/FCV], and each call's bad-input status.
#include "rs4_fixture.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rs4sim::rpc {
namespace {

class RpcDeviceTest : public RpcRs4Test {
 protected:
  v1::Empty empty_;

  grpc::Status set_power(std::uint32_t address, bool on) {
    v1::SetPowerRequest req;
    req.set_address(address);
    req.set_on(on);
    return unary(*device_stub_, &v1::Device::Stub::SetPower, req, empty_);
  }
  grpc::Status power_cycle(std::uint32_t address) {
    return unary(*device_stub_, &v1::Device::Stub::PowerCycle, station_request(address), empty_);
  }
  grpc::Status contour(std::uint32_t address, v1::Contour& out) {
    return unary(*observation_stub_, &v1::Observation::Stub::GetContour, station_request(address),
                 out);
  }
  grpc::Status clear_scene(std::uint32_t address) {
    return unary(*device_stub_, &v1::Device::Stub::ClearScene, station_request(address), empty_);
  }
  grpc::Status pc_adapter(bool attached) {
    v1::SetPcAdapterRequest req;
    req.set_address(4);
    req.set_attached(attached);
    return unary(*device_stub_, &v1::Device::Stub::SetPcAdapter, req, empty_);
  }
  grpc::Status switches(std::uint32_t address, std::uint32_t high, std::uint32_t low) {
    v1::SetAddressSwitchesRequest req;
    req.set_address(address);
    req.set_high(high);
    req.set_low(low);
    return unary(*device_stub_, &v1::Device::Stub::SetAddressSwitches, req, empty_);
  }
  grpc::Status fault(bool inject, v1::Fault which) {
    v1::FaultRequest req;
    req.set_address(4);
    req.set_fault(which);
    return inject ? unary(*device_stub_, &v1::Device::Stub::InjectFault, req, empty_)
                  : unary(*device_stub_, &v1::Device::Stub::ClearFault, req, empty_);
  }
  grpc::Status exchange(std::uint32_t address, std::uint32_t serial) {
    v1::ExchangeScannerRequest req;
    req.set_address(address);
    req.set_serial_number(serial);
    return unary(*device_stub_, &v1::Device::Stub::ExchangeScanner, req, empty_);
  }
  v1::ParameterSetDocument parameter_set() {
    v1::ParameterSetDocument out;
    const auto status =
        unary(*device_stub_, &v1::Device::Stub::GetParameterSet, station_request(4), out);
    EXPECT_TRUE(status.ok()) << status.error_message();
    return out;
  }
  grpc::Status set_parameter_set(const std::string& json, v1::ParameterSetDocument& out) {
    v1::SetParameterSetRequest req;
    req.set_address(4);
    req.set_json(json);
    return unary(*device_stub_, &v1::Device::Stub::SetParameterSet, req, out);
  }
  // The factory document, written by hand for rs4/param_doc's tests (docs/param.md), with
  // the unit's serial number: the only key a unit's factory set differs in.
  static std::string factory_document(std::uint32_t serial) {
    std::ifstream in(std::string(RS4SIM_PARAM_DOC_DATA) + "/factory_default.json");
    std::stringstream text;
    text << in.rdbuf();
    std::string doc = text.str();
    const std::string key = "\"serial_number\": 0,";
    const auto at = doc.find(key);
    EXPECT_NE(at, std::string::npos);
    if (at != std::string::npos) {
      doc.replace(at, key.size(), "\"serial_number\": " + std::to_string(serial) + ",");
    }
    return doc;
  }
  v1::ListDevicesResponse devices() {
    grpc::ClientContext ctx;
    v1::ListDevicesResponse out;
    EXPECT_TRUE(device_stub_->ListDevices(&ctx, v1::ListDevicesRequest{}, &out).ok());
    return out;
  }
  double now_s() {
    grpc::ClientContext ctx;
    v1::TimeResponse t;
    EXPECT_TRUE(time_stub_->Now(&ctx, v1::Empty{}, &t).ok());
    return static_cast<double>(t.now_ns()) / 1e9;
  }
};

TEST_F(RpcDeviceTest, ListDevicesNamesTheRunsRs4AndItsPower) {
  auto list = devices();
  ASSERT_EQ(list.devices_size(), 1);
  EXPECT_EQ(list.devices(0).address(), 4U);
  EXPECT_EQ(list.devices(0).kind(), "rs4");
  EXPECT_TRUE(list.devices(0).powered());
  ASSERT_TRUE(set_power(4, false).ok());
  EXPECT_FALSE(devices().devices(0).powered());
}

TEST_F(RpcDeviceTest, PowerOffDarkensTheRs4AndPowerOnBootsItAgain) {
  boot();
  ASSERT_TRUE(set_power(4, false).ok());
  auto s = state();
  EXPECT_FALSE(s.powered());
  EXPECT_EQ(s.rs4_state(), "off");
  EXPECT_EQ(s.led(), "dark");
  EXPECT_FALSE(s.ossd());
  advance(1000);  // beyond the segment master's DP watchdog: the slave is lost
  EXPECT_FALSE(state().connected());
  ASSERT_TRUE(set_power(4, true).ok());
  EXPECT_EQ(state().rs4_state(), "initialisation");
  const double on_at = now_s();
  ASSERT_TRUE(run_until(v1::CONDITION_RS4_MEASURING, 40'000));
  EXPECT_GE(now_s() - on_at, 29.9);  // the boot until operational [RS4 manual §1]
  EXPECT_TRUE(state().connected());
}

TEST_F(RpcDeviceTest, PowerCycleRestartsTheBootAndDropsTheOssds) {
  boot();
  ASSERT_TRUE(state().ossd());
  ASSERT_TRUE(power_cycle(4).ok());
  const auto s = state();
  EXPECT_TRUE(s.powered());
  EXPECT_EQ(s.rs4_state(), "initialisation");
  EXPECT_FALSE(s.ossd());
  const double at = now_s();
  ASSERT_TRUE(run_until(v1::CONDITION_RS4_MEASURING, 40'000));
  EXPECT_GE(now_s() - at, 29.9);
}

// A round post of radius 300 mm, 4 m straight ahead: the beam at 90° (segment 264 of 529
// over 190°, [RS4 manual §5.2.3.4]) meets it at 4000 − 300 = 3700 mm.
TEST_F(RpcDeviceTest, TheContourShowsTheSceneAndClearSceneRestoresTheEmptyOne) {
  boot();
  advance(100);
  v1::Contour empty;
  ASSERT_TRUE(contour(4, empty).ok());
  ASSERT_EQ(empty.mm_size(), 529);
  grpc::ClientContext ctx;
  v1::AddObstacleRequest add;
  add.set_address(4);
  add.mutable_circle()->mutable_centre()->set_x(0);
  add.mutable_circle()->mutable_centre()->set_y(4000);
  add.mutable_circle()->set_radius(300);
  v1::AddObstacleResponse id;
  ASSERT_TRUE(device_stub_->AddObstacle(&ctx, add, &id).ok());
  advance(100);  // two scans of 40 ms
  v1::Contour post;
  ASSERT_TRUE(contour(4, post).ok());
  ASSERT_EQ(post.mm_size(), 529);
  EXPECT_EQ(post.mm(264), 3700U);
  EXPECT_GT(post.scan_number(), empty.scan_number());
  EXPECT_NE(post.mm(264), empty.mm(264));
  ASSERT_TRUE(clear_scene(4).ok());
  advance(100);
  v1::Contour cleared;
  ASSERT_TRUE(contour(4, cleared).ok());
  EXPECT_TRUE(
      std::equal(cleared.mm().begin(), cleared.mm().end(), empty.mm().begin(), empty.mm().end()));
}

TEST_F(RpcDeviceTest, ThePcAdapterSwitchesTheRs232ThroughAndItsRemovalRequestsTheProxy) {
  boot();
  ASSERT_TRUE(pc_adapter(true).ok());
  advance(100);
  auto s = state();
  EXPECT_TRUE(s.pc_adapter_attached());
  EXPECT_TRUE(s.input().rs232_active());  // bit 3: switched through [RS4 manual §5.1.1]
  ASSERT_TRUE(pc_adapter(false).ok());
  advance(100);
  s = state();
  EXPECT_FALSE(s.pc_adapter_attached());
  EXPECT_FALSE(s.input().rs232_active());
  EXPECT_TRUE(s.input().proxy_request());  // the set may have changed [RS4 manual §7.2]
}

TEST_F(RpcDeviceTest, AnRs4FaultIsPresentUntilCleared) {
  boot();
  ASSERT_TRUE(fault(true, v1::FAULT_DAZZLED).ok());
  advance(100);
  auto faults = state().faults_present();
  EXPECT_EQ(faults.size(), 1);
  EXPECT_FALSE(state().ossd());
  ASSERT_TRUE(fault(false, v1::FAULT_DAZZLED).ok());
  advance(100);
  EXPECT_EQ(state().faults_present_size(), 0);
  const auto unspecified = fault(true, v1::FAULT_UNSPECIFIED);
  EXPECT_EQ(unspecified.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(unspecified), "fault");
}

TEST_F(RpcDeviceTest, AddressSwitchesTakeEffectAtTheNextPowerOn) {
  boot();
  EXPECT_EQ(state().f_dest_add(), 504U);  // 500 + the DP address [RS4 manual §4.5]
  ASSERT_TRUE(switches(4, 0, 5).ok());
  advance(100);
  EXPECT_EQ(state().f_dest_add(), 504U);  // read at power-on only
  ASSERT_TRUE(power_cycle(4).ok());
  advance(100);
  EXPECT_EQ(state().f_dest_add(), 505U);
}

TEST_F(RpcDeviceTest, ClearedBusFaultsLetTheMasterReachTheStationAgain) {
  ASSERT_TRUE(run_until(v1::CONDITION_DATA_EXCHANGE, 10'000));
  const auto drop =
      bus_fault_request(4, v1::BUS_FAULT_KIND_DROP, v1::DIRECTION_FROM_STATION, 1'000'000);
  v1::BusFaultResponse id;
  ASSERT_TRUE(unary(*faults_stub_, &v1::Faults::Stub::InjectBusFault, drop, id).ok());
  advance(1000);  // every reply lost: retries, then the master counts the slave as lost
  // (The slave still hears the master's requests: only the master's view changes.)
  EXPECT_FALSE(state().plc().data_exchange());
  grpc::ClientContext c2;
  ASSERT_TRUE(faults_stub_->ClearBusFaults(&c2, v1::Empty{}, &empty_).ok());
  advance(2000);  // the master's restart: diagnosis, Set_Prm, Chk_Cfg, data exchange
  EXPECT_TRUE(state().plc().data_exchange());
}

TEST_F(RpcDeviceTest, BadInputGetsASpecificStatus) {
  auto s = switches(4, 16, 0);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "high");
  s = switches(4, 0, 16);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "low");
  s = switches(4, 7, 15);  // 127 must not be used [RS4 manual §4.5]
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "high");
  v1::Contour c;
  s = contour(9, c);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_NE(s.error_message().find("station 9"), std::string::npos) << s.error_message();
  s = set_power(200, true);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "address");
  EXPECT_EQ(power_cycle(9).error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(clear_scene(127).error_code(), grpc::StatusCode::INVALID_ARGUMENT);
}

}  // namespace
}  // namespace rs4sim::rpc

namespace rs4sim::rpc {
namespace {

TEST_F(RpcDeviceTest, GetParameterSetAnswersTheFactoryDocumentOfANewUnit) {
  const auto set = parameter_set();
  EXPECT_EQ(set.serial_number(), 0x00012345U);  // the simulated unit's default identity
  EXPECT_EQ(set.json(), factory_document(0x00012345));
  EXPECT_NE(set.transfer_crc32(), 0U);
}

// The parametrisation tool through the optical PC adapter [RS4 manual §7.2]: the response
// time 80 + 2·40 = 160 ms [RS4 manual §6.6]; the PC adapter is put back as it was (its
// removal raising Proxy-Request is ThePcAdapterSwitchesTheRs232Through…'s).
TEST_F(RpcDeviceTest, SetParameterSetWritesTheDocumentOverTheSet) {
  boot();
  const auto before = parameter_set();
  v1::ParameterSetDocument after;
  const auto status = set_parameter_set(R"({"format": 1, "response_time_ms": 160})", after);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_NE(after.json().find("\"response_time_ms\": 160"), std::string::npos) << after.json();
  EXPECT_NE(after.transfer_crc32(), before.transfer_crc32());
  EXPECT_EQ(parameter_set().json(), after.json());
  // Only the key the document names changed: the rest is the factory document's.
  std::string expected = factory_document(0x00012345);
  const std::string key = "\"response_time_ms\": 80";
  expected.replace(expected.find(key), key.size(), "\"response_time_ms\": 160");
  EXPECT_EQ(after.json(), expected);
  advance(100);
  EXPECT_FALSE(state().pc_adapter_attached());
  // An adapter the user attached stays attached.
  ASSERT_TRUE(pc_adapter(true).ok());
  ASSERT_TRUE(set_parameter_set(R"({"format": 1, "response_time_ms": 200})", after).ok());
  advance(100);
  EXPECT_TRUE(state().pc_adapter_attached());
}

TEST_F(RpcDeviceTest, SetParameterSetRefusesABadDocumentAndKeepsTheSet) {
  boot();
  const auto before = parameter_set();
  v1::ParameterSetDocument out;
  // 100 ms is not 80 + n·40 ms [RS4 manual §6.6].
  auto s = set_parameter_set(R"({"format": 1, "response_time_ms": 100})", out);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "json");
  EXPECT_NE(s.error_message().find("$.response_time_ms"), std::string::npos) << s.error_message();
  s = set_parameter_set(R"({"format": 1, "response_time_ms": )", out);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(parameter_set().json(), before.json());
  ASSERT_TRUE(set_power(4, false).ok());
  s = set_parameter_set(R"({"format": 1, "response_time_ms": 160})", out);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_EQ(parameter_set().json(), before.json());
}

// Issue 39: one run for segments 100..140 of pair 2's protective field left the other
// 529 - 41 = 488 segments at 0 mm and was accepted; now refused with the count unless
// allow_partial_field says it on purpose.
TEST_F(RpcDeviceTest, SetParameterSetRefusesAProtectiveFieldLeftPartlyUnset) {
  boot();
  const auto before = parameter_set();
  const std::string doc =
      R"({"format": 1, "pairs": {"2": {"protective": {"runs": [{"from": 100, "to": 140, )"
      R"("mm": 1850}]}}}})";
  v1::ParameterSetDocument out;
  auto s = set_parameter_set(doc, out);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(s.error_message().find("488 of 529 segments"), std::string::npos) << s.error_message();
  EXPECT_NE(s.error_message().find("allow_partial_field"), std::string::npos);
  EXPECT_EQ(parameter_set().json(), before.json());
  grpc::ClientContext ctx;
  v1::SetParameterSetRequest req;
  req.set_address(4);
  req.set_json(doc);
  req.set_allow_partial_field(true);
  ASSERT_TRUE(device_stub_->SetParameterSet(&ctx, req, &out).ok());
  EXPECT_NE(out.json().find(R"({"from":141,"to":528,"mm":0})"), std::string::npos) << out.json();
}

// A 100 KB document nested 50,000 deep: refused by the linear structure scan before
// protobuf's parser (quadratic in the nesting: it froze the loop for minutes), with the line
// and column of the 102nd bracket; the run answers the next call.
TEST_F(RpcDeviceTest, SetParameterSetRefusesDeepNestingAtOnce) {
  boot();
  v1::ParameterSetDocument out;
  const auto s = set_parameter_set(std::string(50'000, '[') + std::string(50'000, ']'), out);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "json");
  EXPECT_NE(s.error_message().find("not valid JSON at 1:102: nested deeper than 100"),
            std::string::npos)
      << s.error_message();
  EXPECT_TRUE(state().powered());
}

// [RS4 manual §7.1] scenario 4: a new unit with factory settings and its own serial number;
// the RS4 boots again (≈30 s, [RS4 manual §1]).
TEST_F(RpcDeviceTest, ExchangeScannerMountsAFactoryUnitWithItsSerialNumber) {
  boot();
  v1::ParameterSetDocument changed;
  ASSERT_TRUE(set_parameter_set(R"({"format": 1, "response_time_ms": 200})", changed).ok());
  ASSERT_TRUE(exchange(4, 344865).ok());
  const auto s = state();
  EXPECT_TRUE(s.powered());
  EXPECT_EQ(s.rs4_state(), "initialisation");
  EXPECT_FALSE(s.ossd());
  const auto set = parameter_set();
  EXPECT_EQ(set.serial_number(), 344865U);
  EXPECT_EQ(set.json(), factory_document(344865));
  const double at = now_s();
  ASSERT_TRUE(run_until(v1::CONDITION_RS4_MEASURING, 40'000));
  EXPECT_GE(now_s() - at, 29.9);
  EXPECT_LE(now_s() - at, 32.0);
}

TEST_F(RpcDeviceTest, ExchangeScannerRefusesSerialZeroAndAnUnknownStation) {
  auto s = exchange(4, 0);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(bad_field(s), "serial_number");
  EXPECT_EQ(parameter_set().serial_number(), 0x00012345U);  // nothing happened
  s = exchange(9, 1234);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
}

}  // namespace
}  // namespace rs4sim::rpc
