#include "rs4/adapter/rs4_gsd.h"

#include "gsd/device_gsd.h"
#include "gsd/dp_slave_config.h"

#include <stdexcept>

namespace rs4sim::rs4::adapter {

namespace {

// The built-in file parses (tests/gsd/shipped_gsd_test.cpp); value() throws otherwise.
const gsd::Device& device() { return gsd::rs4sim_device().value(); }

}  // namespace

std::uint16_t ident_number() { return device().ident_number; }

std::uint16_t f_dest_add(std::uint8_t address) {
  static const std::uint16_t base = [] {
    for (const auto& [number, p] : device().params) {
      if (p.name == "F_Dest_Add") return static_cast<std::uint16_t>(p.min);
    }
    throw std::logic_error("built-in GSD: no F_Dest_Add parameter");
  }();
  return static_cast<std::uint16_t>(base + address);
}

dp::slave::Config slave_config(std::uint8_t address) {
  const gsd::Device& d = device();
  dp::slave::Config s = gsd::dp_slave_config(d, address);
  s.c2_rm_send_timeout = d.dpv1.c2_response_timeout;
  // Alarm_Sequence_Mode_Count: alarms outstanding and Seq_Nr cycle ([IEC 61158-6-3 DPV1 alarms]).
  s.alarm_sequence_numbers = d.dpv1.alarm_sequence_mode_count;
  return s;
}

}  // namespace rs4sim::rs4::adapter
