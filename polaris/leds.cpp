#include "polaris/leds.h"

namespace rs4sim::polaris {

Leds leds_for(bool occupied, std::optional<std::chrono::nanoseconds> calibrating_for) noexcept {
  if (!calibrating_for) return {Led::kYellow, occupied ? Led::kRed : Led::kGreen};
  return {Led::kYellowFlashing, *calibrating_for < kCalibrationGreen ? Led::kGreen : Led::kRedGreen};
}

std::string_view to_token(Led led) noexcept {
  switch (led) {
    case Led::kOff: return "off";
    case Led::kYellow: return "yellow";
    case Led::kYellowFlashing: return "yellow-flashing";
    case Led::kGreen: return "green";
    case Led::kRed: return "red";
    case Led::kRedGreen: return "red-green";
  }
  return "off";
}

}  // namespace rs4sim::polaris
