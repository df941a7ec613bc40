#include "modbus/timing.h"

#include <chrono>

namespace rs4sim::modbus {

namespace {
constexpr std::uint32_t kFixedAbove = 19200;
}  // namespace

stream::Duration t1_5(const stream::LineSettings& s) {
  if (s.baud > kFixedAbove) return std::chrono::microseconds(750);
  return stream::character_time(s, 1.5);
}

stream::Duration t3_5(const stream::LineSettings& s) {
  if (s.baud > kFixedAbove) return std::chrono::microseconds(1750);
  return stream::character_time(s, 3.5);
}

}  // namespace rs4sim::modbus
