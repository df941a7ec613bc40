// A GSD station's F-module as a PROFIsafe F-device (gsd/f_device_module.h), driven through the
// station's byte images by our F-host, for the project's V1 and V2 F-module files
// (corpus/f_module_v1.gsd, f_module_v2.gsd; their F_Par_CRC are the makers' 0x783E and 0xBB95).
#include "gsd/f_device_module.h"
#include "gsd/interp.h"
#include "profisafe/f_host.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <vector>

namespace rs4sim::gsd {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

struct Rig {
  Rig(const std::string& file, const std::vector<std::string>& modules, std::uint16_t dest) {
    auto d = parse(testing::corpus(file), file);
    EXPECT_TRUE(d) << (d ? "" : d.error().what());
    device = d.value();
    auto c = configure(device, {modules, {}});
    EXPECT_TRUE(c) << (c ? "" : c.error().what());
    setup = c.value();
    auto f = FModuleDevice::make(device, setup, setup.f_parameters.at(0), 0, 0, dest);
    EXPECT_TRUE(f) << (f ? "" : f.error().what());
    fdev.emplace(std::move(f).value());
    inputs.assign(setup.input_len, 0);
  }
  // One DP cycle: the host's PDU in the output image, the device's answer in the input image.
  profisafe::FHostEvent cycle(profisafe::FHost& host) {
    now += 10ms;
    const auto req = host.request(now);
    Bytes outputs(setup.output_len, 0);
    std::copy(req.begin(), req.end(), outputs.begin());
    fdev->on_outputs(outputs, now);
    fdev->write_inputs(inputs, now);
    return host.on_pdu(std::span(inputs).first(req.size()), now);
  }
  Device device;
  SlaveSetup setup;
  std::optional<FModuleDevice> fdev;
  Bytes inputs;
  profisafe::TimePoint now{std::chrono::hours(1)};
};

void reaches_run_both_ways(Rig& rig, std::size_t pdu_size) {
  ASSERT_TRUE(rig.fdev->set_parameters(rig.setup.user_prm_data).ok());
  profisafe::FHost host({rig.setup.f_parameters[0].parameters, rig.fdev->f_data_size(), {}});
  const Bytes in(rig.fdev->f_data_size(), 0x5A), out(rig.fdev->f_data_size(), 0xC3);
  rig.fdev->set_f_inputs(in);
  host.set_output(out);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(rig.cycle(host), profisafe::FHostEvent::kValid);
  EXPECT_EQ(host.request(rig.now).size(), pdu_size);
  EXPECT_EQ(host.state(), profisafe::FHostState::kRun);
  EXPECT_EQ(Bytes(host.input().begin(), host.input().end()), in);
  EXPECT_EQ(Bytes(rig.fdev->f_outputs().begin(), rig.fdev->f_outputs().end()), out);
  // A CRC2 fault on the device's side passivates the host until ACK_REI.
  rig.fdev->device().faults().corrupt_crc2 = 1;
  EXPECT_EQ(rig.cycle(host), profisafe::FHostEvent::kCrcError);
  EXPECT_EQ(host.input()[0], 0);  // substitute value
  for (int i = 0; i < 3; ++i) (void)rig.cycle(host);
  ASSERT_TRUE(host.ack_req());
  host.ack_rei();
  (void)rig.cycle(host);
  EXPECT_EQ(Bytes(host.input().begin(), host.input().end()), in);
}

TEST(GsdFModuleDevice, V1ModuleReachesRunWithOurFHost) {
  Rig rig("f_module_v1.gsd", {"PROFIsafe v1.x Module"}, 1);
  EXPECT_EQ(rig.fdev->device().version(), profisafe::ProtocolVersion::kV1);
  reaches_run_both_ways(rig, 8);  // 4 F-data + status/control + number + 2-byte CRC2
}

TEST(GsdFModuleDevice, V2PresetModuleReachesRunWithOurFHost) {
  Rig rig("f_module_v2.gsd", {}, 1);
  EXPECT_EQ(rig.fdev->device().version(), profisafe::ProtocolVersion::kV2);
  reaches_run_both_ways(rig, 12);  // 8 F-data + status/control + 3-byte CRC2
}

// The device's own F_Dest_Add (its address switch) 2, the host's 1: diagnosis 64 in the status
// block of slot 0 ([IEC 61784-3-3 F-Parameters]); a F_WD_Time outside the GSD's 10..10000: 67.
TEST(GsdFModuleDevice, FParameterFaultsGiveTheStandardDiagnosisInTheStatusBlock) {
  Rig rig("f_module_v1.gsd", {"PROFIsafe v1.x Module"}, 2);
  EXPECT_FALSE(rig.fdev->set_parameters(rig.setup.user_prm_data).ok());
  EXPECT_EQ(rig.fdev->status_block(), (std::array<std::uint8_t, 5>{0x05, 0x81, 0x00, 0x00, 64}));
  EXPECT_EQ(rig.fdev->device().state(), profisafe::FDeviceState::kNoParameters);
  Rig wd("f_module_v1.gsd", {"PROFIsafe v1.x Module"}, 1);
  profisafe::FParameters p = wd.setup.f_parameters[0].parameters;
  p.wd_time_ms = 5;
  Bytes user = wd.setup.user_prm_data;
  const auto block = profisafe::encode_f_parameters(p);
  std::copy(block.begin(), block.end(), user.begin());
  EXPECT_EQ(wd.fdev->set_parameters(user).fault, profisafe::FParameterFault::kWdTimeInvalid);
  EXPECT_EQ(wd.fdev->diagnosis(), 67);
  EXPECT_EQ(wd.fdev->set_parameters(Bytes{1, 2}).fault,
            profisafe::FParameterFault::kVersionMismatch);  // no block at all: 70
}

}  // namespace
}  // namespace rs4sim::gsd
