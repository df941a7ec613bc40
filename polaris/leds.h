#pragma once
// The barrier's LEDs [Polaris manual §5.1] [Polaris manual §7.2]: "The YELLOW LED on the TX
// indicates that the device is powered on"; "The RED/GREEN LED on the RX indicates whether
// the detection area is free (GREEN) or occupied (RED)". During auto-calibration "the yellow
// LED on the transmitter flashes quickly until the procedure is finished. On the receiver,
// the green LED turns on for 5 seconds and then flashes red/green until the auto-calibration
// is finished."

#include <chrono>
#include <cstdint>
#include <optional>
#include <string_view>

namespace rs4sim::polaris {

enum class Led : std::uint8_t {
  kOff,
  kYellow,          // TX: powered
  kYellowFlashing,  // TX: "flashes quickly" while calibrating
  kGreen,           // RX: area free; the first 5 s of a calibration
  kRed,             // RX: area occupied
  kRedGreen,        // RX: "flashes red/green" until the calibration ends
};

struct Leds {
  Led tx = Led::kYellow;
  Led rx = Led::kGreen;
  friend bool operator==(const Leds&, const Leds&) = default;
};

// "the green LED turns on for 5 seconds" [Polaris manual §7.2].
inline constexpr std::chrono::seconds kCalibrationGreen{5};

// `calibrating_for`: how long the running calibration has run (nullopt: none runs).
[[nodiscard]] Leds leds_for(bool occupied,
                            std::optional<std::chrono::nanoseconds> calibrating_for) noexcept;
// "off", "yellow", "yellow-flashing", "green", "red", "red-green": the API's word.
[[nodiscard]] std::string_view to_token(Led led) noexcept;

}  // namespace rs4sim::polaris
