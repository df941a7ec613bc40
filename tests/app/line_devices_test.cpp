// The one list of line devices (RS4SIM_LINE_DEVICES, the root CMakeLists.txt) reaches every
// place that used to list them by hand: the run's device registry (the generated
// line_device_entries()), the gRPC side (the generated rpc::line_apis(): each device's service
// and watcher) and the capture's protocol byte (the description's LinkKind). The expected words,
// service names and capture numbers are written out here from docs/rpc.md, devices.proto and
// docs/capture.md, not read from the code under test.
#include "rpc/line_devices.h"

#include "app/devices/device_registry.h"
#include "gridscan/device.h"
#include "metron/device.h"
#include "polaris/device.h"

#include <gtest/gtest.h>

#include <google/protobuf/descriptor.h>

#include <iterator>
#include <string>
#include <typeinfo>
#include <vector>

namespace rs4sim::app {
namespace {

struct Expected {
  const char* word;     // --device
  const char* service;  // devices.proto
  int capture;          // the protocol byte of a line capture's records (docs/capture.md)
};
const Expected kLineDevices[] = {
    {"gridscan", "rs4sim.v1.GridScan", 1},
    {"metron", "rs4sim.v1.Metron", 2},
    {"polaris", "rs4sim.v1.Polaris", 3},
};

TEST(LineDevices, TheRegistryListsThemAfterTheOthersInTheListsOrder) {
  std::vector<std::string> names;
  for (const auto& e : device_registry()) names.push_back(e.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"rs4", "generic", "echo", "gridscan", "metron", "polaris"}));
  ASSERT_EQ(line_device_entries().size(), std::size(kLineDevices));
  ASSERT_EQ(rpc::line_apis().size(), std::size(kLineDevices));
}

TEST(LineDevices, EachEntryHasItsServiceItsWordAndItsCaptureProtocol) {
  for (const auto& x : kLineDevices) {
    SCOPED_TRACE(x.word);
    const DeviceEntry* e = find_device(x.word);
    ASSERT_NE(e, nullptr);
    EXPECT_TRUE(e->byte_device);
    EXPECT_EQ(stream::to_string(e->kind), x.word);
    const rpc::LineApi* api = rpc::find_line_api(e->kind);
    ASSERT_NE(api, nullptr);
    EXPECT_EQ(api->service, x.service);
    // The name is a service of the API's .proto files (the generated descriptors).
    EXPECT_NE(google::protobuf::DescriptorPool::generated_pool()->FindServiceByName(api->service),
              nullptr);
    DeviceOptions o;
    e->validate(o);
    const auto segment = e->simulate(o);
    EXPECT_EQ(static_cast<int>(segment->line_protocol()), x.capture);
  }
  // The others have no line device's API.
  for (const char* other : {"rs4", "generic", "echo"}) {
    EXPECT_EQ(rpc::find_line_api(find_device(other)->kind), nullptr) << other;
  }
}

TEST(LineDevices, AnApiTakesItsOwnDevicesCoreOnly) {
  const gridscan::Device grid{gridscan::Options{}};
  const metron::Device metron{metron::Options{}};
  const auto& grid_api = *rpc::find_line_api(stream::DeviceKind::kGridScan);
  const auto& metron_api = *rpc::find_line_api(stream::DeviceKind::kMetron);
  const auto watcher = grid_api.watcher(7, grid);
  ASSERT_NE(watcher, nullptr);
  EXPECT_EQ(watcher->address(), 7);
  EXPECT_THROW((void)metron_api.watcher(0, grid), std::bad_cast);
  EXPECT_THROW((void)grid_api.watcher(0, metron), std::bad_cast);
  EXPECT_NE(metron_api.watcher(0, metron), nullptr);
}

}  // namespace
}  // namespace rs4sim::app
