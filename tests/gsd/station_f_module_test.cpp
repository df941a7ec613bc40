// A GSD station's F-module is a PROFIsafe F-device (gsd/station/gsd_station.h): the station's
// application fed the Set_Prm our master sends (gsd::master_entry) and the F-host's PDUs in its
// output image, for the project's V1 and V2 F-module files (corpus/f_module_v1.gsd,
// f_module_v2.gsd).
#include "gsd/interp.h"
#include "gsd/station/gsd_station.h"
#include "profisafe/f_host.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

namespace rs4sim::gsd {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

GsdStationSpec spec_of(const std::string& file, const std::vector<std::string>& modules,
                       std::optional<std::uint16_t> f_dest_add = std::nullopt) {
  auto d = parse(testing::corpus(file), file);
  EXPECT_TRUE(d) << (d ? "" : d.error().what());
  auto device = std::make_shared<const Device>(d.value());
  auto c = configure(*device, {modules, {}});
  EXPECT_TRUE(c) << (c ? "" : c.error().what());
  GsdStationSpec spec = station_spec(file, device, c.value(), 7);
  spec.f_dest_add = f_dest_add;
  return spec;
}

// Our master's Set_Prm, then host ↔ station cycles through the images.
void reaches_run(const GsdStationSpec& spec, std::size_t module) {
  GsdApplication app(spec);
  profisafe::TimePoint now{std::chrono::hours(1)};
  ASSERT_EQ(app.check_parameters(master_entry(spec, 100ms).value().prm, now),
            dp::slave::PrmVerdict::kAccept)
      << app.prm_fault();
  ASSERT_EQ(app.f_modules().size(), 1U);
  const auto& io = spec.modules[module];
  const FParameterBlock& block = spec.setup.f_parameters[0];
  const std::size_t size = app.f_modules()[0].f_data_size();
  profisafe::FHost host({block.parameters, size, {}});
  const Bytes in(size, 0x6B);
  ASSERT_FALSE(app.set_inputs(module, in));
  Bytes outputs(spec.setup.output_len, 0), inputs(spec.setup.input_len, 0);
  for (int i = 0; i < 3; ++i) {
    now += 10ms;
    const auto req = host.request(now);
    std::copy(req.begin(), req.end(), outputs.begin() + static_cast<std::ptrdiff_t>(io.output_offset));
    app.on_outputs(outputs, now);
    app.read_inputs(inputs, now);
    EXPECT_EQ(host.on_pdu(std::span(inputs).subspan(io.input_offset, req.size()), now),
              profisafe::FHostEvent::kValid);
  }
  EXPECT_EQ(host.state(), profisafe::FHostState::kRun);
  EXPECT_EQ(Bytes(host.input().begin(), host.input().end()), in);
  // The F-module's own input bytes are the device's PDU, not settable as plain bytes.
  EXPECT_TRUE(app.set_inputs(module, Bytes(io.input_len, 0)));
}

TEST(GsdStationFModule, V1ModuleAfterAStandardModuleReachesRun) {
  reaches_run(spec_of("f_module_v1.gsd", {"Standard telegram 1, PZD-2/2", "PROFIsafe v1.x Module"}),
              1);
}

TEST(GsdStationFModule, V2PresetModuleReachesRun) {
  reaches_run(spec_of("f_module_v2.gsd", {"AS-i 16 bytes in/out"}), 0);
}

// The station's address switch for its F-device says F_Dest_Add 2, the master's block 1:
// Prm_Fault with the standard diagnosis 64 in the status block of slot 0.
TEST(GsdStationFModule, WrongFDestAddIsPrmFaultWithDiagnosis64) {
  const GsdStationSpec spec = spec_of("f_module_v2.gsd", {}, 2);
  GsdApplication app(spec);
  EXPECT_EQ(app.check_parameters(master_entry(spec, 100ms).value().prm, {}),
            dp::slave::PrmVerdict::kPrmFault);
  EXPECT_NE(app.prm_fault().find("F-module in slot 0: diagnosis 64"), std::string::npos)
      << app.prm_fault();
  EXPECT_EQ(Bytes(app.diagnosis_blocks().begin(), app.diagnosis_blocks().end()),
            (Bytes{0x05, 0x81, 0x00, 0x00, 64}));
  EXPECT_EQ(app.f_modules()[0].device().state(), profisafe::FDeviceState::kNoParameters);
}

}  // namespace
}  // namespace rs4sim::gsd
