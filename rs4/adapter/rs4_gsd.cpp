#include "rs4/adapter/rs4_gsd.h"

#include "gsd/device_gsd.h"

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
  dp::slave::Config s;
  s.address = address;
  s.ident_number = d.ident_number;
  s.sync_supported = d.sync_mode;
  s.freeze_supported = d.freeze_mode;
  s.set_slave_add_supported = d.set_slave_add;
  s.max_diag_length = d.max_diag_data_len;
  s.dpv1 = d.dpv1.slave;
  s.fail_safe_supported = d.fail_safe;
  s.wd_base_1ms_supported = d.dpv1.wd_base_1ms;
  s.c1_max_data_length = d.dpv1.c1_max_data_len;
  s.c2_supported = d.dpv1.c2_read_write;
  s.c2_max_data_length = d.dpv1.c2_max_data_len;
  s.c2_rm_send_timeout = d.dpv1.c2_response_timeout;
  // Alarm_Sequence_Mode_Count: alarms outstanding and Seq_Nr cycle ([IEC 61158-6-3 DPV1 alarms]).
  s.alarm_capacity = d.dpv1.alarm_sequence_mode_count;
  s.alarm_sequence_numbers = d.dpv1.alarm_sequence_mode_count;
  return s;
}

}  // namespace rs4sim::rs4::adapter
