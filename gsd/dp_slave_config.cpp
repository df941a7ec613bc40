#include "gsd/dp_slave_config.h"

namespace rs4sim::gsd {

dp::slave::Config dp_slave_config(const Device& d, std::uint8_t address) {
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
  if (d.dpv1.c1_max_data_len != 0) s.c1_max_data_length = d.dpv1.c1_max_data_len;
  s.c2_supported = d.dpv1.c2_read_write;
  if (d.dpv1.c2_max_data_len != 0) s.c2_max_data_length = d.dpv1.c2_max_data_len;
  if (d.dpv1.alarm_sequence_mode_count != 0) {
    s.alarm_capacity = d.dpv1.alarm_sequence_mode_count;
  }
  return s;
}

}  // namespace rs4sim::gsd
