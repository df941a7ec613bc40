#pragma once
// Shared fixture of the RS4 device integration tests: master (from the shipped GSD) +
// F-host + Rs4Device on the memory bus, on the manual clock (no sleeps anywhere).

#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_segment.h"

#include <gtest/gtest.h>

#include <chrono>
#include <variant>

namespace rs4sim::rs4::device::testing {

using namespace std::chrono_literals;
using adapter::kInputOperatingState;
using adapter::kInputOssd;
using adapter::kInputProtectiveField;
using adapter::kInputProxyRequest;
using adapter::kOutputRestart;

// Boot time of the device ([RS4 manual §7.1.1]: ≈30 s) and adapter init (2–3 s) as configured
// below.
inline constexpr auto kBoot = 30s;

inline Rs4SegmentConfig segment_config(std::uint8_t address = 4) {
  Rs4SegmentConfig c;
  c.device.switches = switches_for(address);
  c.master.address = address;
  return c;
}

// Time from `start` until `pred` holds, or nullopt after `limit`.
template <class Pred>
std::optional<dp::Duration> time_until(Rs4Segment& s, Pred pred, dp::Duration limit) {
  const auto start = s.now();
  if (!s.run_until(pred, limit)) return std::nullopt;
  return s.now() - start;
}

// Powered, in data exchange, RS4 booted, restart pulse given: OSSD bit 1 at the F-host.
inline void bring_to_ossd_on(Rs4Segment& s) {
  s.power_on();
  ASSERT_TRUE(s.run_until([&] { return s.in_data_exchange(); }, 5s));
  ASSERT_TRUE(s.run_until([&] { return (s.input_byte() & kInputProxyRequest) != 0; }, kBoot + 1s));
  s.set_output_byte(kOutputRestart | 0x01);  // restart pulse 0.2 s ([RS4 manual §2.3, §2.4]: 0.12–5
                                             // s)
  s.run_for(200ms);
  s.set_output_byte(0x01);
  ASSERT_TRUE(s.run_until([&] { return (s.input_byte() & kInputOssd) != 0; }, 500ms));
}

template <class E>
std::vector<E> events_of(const Rs4Segment& s) {
  std::vector<E> out;
  for (const auto& e : s.events()) {
    if (const auto* x = std::get_if<E>(&e)) out.push_back(*x);
  }
  return out;
}

}  // namespace rs4sim::rs4::device::testing
