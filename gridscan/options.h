#pragma once
// The options of one emulated GridScan/Pro SI, RC type
// ([GridScan manual §4.3, §9.1, §11, §17]); validated once, before the device is built. Defaults: a
// 22-element edge
// ("GRS/Pro SY-2500-22, RC"), blanking mode, door open, polling after power-up.

#include "gridscan/payload.h"
#include "stream/clock.h"
#include "stream/line_settings.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace rs4sim::gridscan {

// 115200 bit/s, 8N1, fixed ([GridScan manual §9.1]).
inline constexpr stream::LineSettings kLineSettings{115200, 8, stream::Parity::kNone, 1};

struct Options {
  unsigned elements = 22;                                  // 12..60 ([GridScan manual §4.3])
  Configuration configuration = Configuration::kBlanking;  // the delivery mode
  // EXTENSION: the communication mode entered after power-up (the manual: always polling).
  CommMode power_up_mode = CommMode::kPolling;
  std::string sw_version = "01.02";  // "xx.yy"
  std::string hw_version = "03.04";
  std::string part_number = "116000";  // 6 ASCII digits
  // t_CYCLE; unset: the typical value, 30 ms at 22 and 62 ms at 60 elements, linear in
  // between and beyond (DECISION, [GridScan manual §11] gives only 22 and 60).
  std::optional<stream::Duration> cycle;
  stream::Duration ready_time = std::chrono::milliseconds(1700);  // power-up, max
  stream::Duration config_window = std::chrono::seconds(120);     // [GridScan manual §10.4]
  // Silence that ends a frame, in character times (DECISION: the manual gives no rule).
  double idle_gap_chars = 3.5;
  // Alignment mode armed for this power-up, as on the first one ([GridScan manual §10.1.3]).
  bool alignment_armed = false;
  // The initial scene.
  std::optional<unsigned> door_position;  // unset: door open (= elements)
  std::uint64_t blocked = 0;              // bit e-1 = element e
  std::uint8_t soiling = 0;               // 0..3
  std::uint16_t alignment_value = 1000;

  // Empty when usable, else what is wrong, e.g. "elements 61 outside 12..60".
  [[nodiscard]] std::string validate() const;
  [[nodiscard]] stream::Duration cycle_time() const;
  [[nodiscard]] stream::Duration idle_gap() const;
};

// Typical t_CYCLE of an edge with n elements (DECISION above).
[[nodiscard]] stream::Duration typical_cycle(unsigned elements);

// The band of t_CYCLE the manual gives: 18..40 ms at 22 elements, 48..76 ms at 60
// [GridScan manual §11] (Table 1, min and max); other counts linear between and beyond, as
// the typical value (DECISION).
struct CycleRange {
  stream::Duration min;
  stream::Duration max;
};
[[nodiscard]] CycleRange cycle_range(unsigned elements);
// "" when `cycle` is inside cycle_range(elements), else why, e.g. "t_CYCLE 17 ms outside
// 18..40 ms for 22 elements [GridScan manual §11]". What a user sets (CLI, API) is held to it.
[[nodiscard]] std::string check_cycle(unsigned elements, stream::Duration cycle);

}  // namespace rs4sim::gridscan
