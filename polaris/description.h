#pragma once
// The Polaris described once (stream/device_description.h): what the CLI, the API
// (rs4sim.v1.Polaris, its Counters message), the end-of-run summary and the run's station list
// read.

#include "polaris/device.h"
#include "stream/device_description.h"

namespace rs4sim::polaris {

using Description = stream::DeviceDescription<Device, Counters>;

[[nodiscard]] const Description& description();

}  // namespace rs4sim::polaris
