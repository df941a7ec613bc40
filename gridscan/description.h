#pragma once
// The GridScan described once (stream/device_description.h): what the CLI, the API
// (rs4sim.v1.GridScan, its Counters message), the end-of-run summary and the run's station list
// read.

#include "gridscan/device.h"
#include "stream/device_description.h"

namespace rs4sim::gridscan {

using Description = stream::DeviceDescription<Device, Counters>;

[[nodiscard]] const Description& description();

}  // namespace rs4sim::gridscan
