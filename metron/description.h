#pragma once
// The METRON described once (stream/device_description.h): what the CLI, the API
// (rs4sim.v1.Metron, MetronCounters), the end-of-run summary and the run's station list read.

#include "metron/device.h"
#include "stream/device_description.h"

namespace rs4sim::metron {

using Description = stream::DeviceDescription<Device, Counters>;

// Every counter of metron/counters.h, E1..E5 as one repeated field.
[[nodiscard]] const Description& description();

}  // namespace rs4sim::metron
