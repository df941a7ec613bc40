#pragma once
// The LEDs of the two edges ([GridScan manual §13], tables 2 and 3).

#include <cstdint>
#include <string_view>

namespace rs4sim::gridscan {

enum class Led : std::uint8_t {
  kOff,
  kOn,
  kBlinkSlow,  // red: start-up
  kBlinkFast,  // red, 5 Hz: internal malfunction
  kBlink1Hz,   // green: static mode configured (up to 2 min after power-up)
};

struct Leds {
  Led rx_green = Led::kOff;
  Led rx_red = Led::kOff;
  Led tx_green = Led::kOff;  // power
  friend bool operator==(const Leds&, const Leds&) = default;
};

struct LedInputs {
  bool powered = false;
  bool starting = false;  // before the power-up Reduced state went out
  bool internal_failure = false;
  bool static_blink = false;  // static mode and within 120 s of power-up
  bool interrupted = false;   // bit 8 of the state
};

[[nodiscard]] Leds leds_for(const LedInputs& in) noexcept;
[[nodiscard]] std::string_view to_string(Led led) noexcept;
// The API's and the event stream's word: "off", "on", "blink-slow", "blink-fast", "blink-1hz".
[[nodiscard]] std::string_view to_token(Led led) noexcept;

}  // namespace rs4sim::gridscan
