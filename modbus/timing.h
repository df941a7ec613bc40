#pragma once
// The RTU silent intervals [Modbus serial line V1.02 §2.5.1.1]: a frame ends after 3.5
// character times of silence, and a gap of more than 1.5 characters inside a frame breaks
// it. Above 19200 baud the spec fixes t1.5 = 750 µs and t3.5 = 1750 µs.

#include "stream/clock.h"
#include "stream/line_settings.h"

namespace rs4sim::modbus {

[[nodiscard]] stream::Duration t1_5(const stream::LineSettings& s);
[[nodiscard]] stream::Duration t3_5(const stream::LineSettings& s);

}  // namespace rs4sim::modbus
