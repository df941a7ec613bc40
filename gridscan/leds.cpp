#include "gridscan/leds.h"

namespace rs4sim::gridscan {

Leds leds_for(const LedInputs& in) noexcept {
  Leds l;
  if (!in.powered) return l;
  l.tx_green = Led::kOn;
  if (in.starting) {
    l.rx_red = Led::kBlinkSlow;
  } else if (in.internal_failure) {
    l.rx_red = Led::kBlinkFast;
  } else if (in.static_blink) {
    l.rx_green = Led::kBlink1Hz;
  } else if (in.interrupted) {
    l.rx_red = Led::kOn;
  } else {
    l.rx_green = Led::kOn;
  }
  return l;
}

std::string_view to_string(Led led) noexcept {
  switch (led) {
    case Led::kOff: return "off";
    case Led::kOn: return "on";
    case Led::kBlinkSlow: return "slow blink";
    case Led::kBlinkFast: return "fast blink (5 Hz)";
    case Led::kBlink1Hz: return "blink 1 Hz";
  }
  return "?";
}

std::string_view to_token(Led led) noexcept {
  switch (led) {
    case Led::kOff: return "off";
    case Led::kOn: return "on";
    case Led::kBlinkSlow: return "blink-slow";
    case Led::kBlinkFast: return "blink-fast";
    case Led::kBlink1Hz: return "blink-1hz";
  }
  return "?";
}

}  // namespace rs4sim::gridscan
