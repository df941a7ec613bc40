#include "rs4/safety/profile.h"

namespace rs4sim::rs4::safety {

profisafe::DeviceProfile device_profile(unsigned dp_address) noexcept {
  profisafe::DeviceProfile d;
  d.check_ipar = false;
  d.sil = profisafe::Sil::kSil2;
  d.crc_length = profisafe::CrcLength::k2Byte;
  d.block_id = 0;
  d.par_version = 0;
  d.min_source_add = 1;
  d.max_source_add = 65534;
  d.min_wd_time_ms = 10;
  d.max_wd_time_ms = 1000;
  d.dest_add = f_dest_add(dp_address);
  return d;
}

}  // namespace rs4sim::rs4::safety
