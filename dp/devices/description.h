#pragma once
// The generic DP slave described once (stream/device_description.h): a slave by its
// Ident_Number and Cfg, or by its GSD file (the GSD station); its kind, link, address rule
// and the options of `rs4sim run --device generic`. Its API (rs4sim.v1.GsdStations) has no
// counters message: the description lists none.

#include "dp/devices/generic_device.h"
#include "stream/device_description.h"

namespace rs4sim::dp::devices {

using Description = stream::DeviceDescription<GenericDevice, stream::NoCounters>;

[[nodiscard]] const Description& description();

}  // namespace rs4sim::dp::devices
