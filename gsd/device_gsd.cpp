#include "gsd/device_gsd.h"

#include "gsd/interp.h"

namespace rs4sim::gsd {

namespace detail {
// Generated from files/RSIM5234.gsd by gsd/CMakeLists.txt (embedded_gsd.cpp.in).
extern const unsigned char kEmbeddedGsd[];
extern const std::size_t kEmbeddedGsdSize;
}  // namespace detail

std::string_view rs4sim_gsd_text() noexcept {
  return {reinterpret_cast<const char*>(detail::kEmbeddedGsd), detail::kEmbeddedGsdSize};
}

const Result<Device>& rs4sim_device() {
  static const Result<Device> device = parse(rs4sim_gsd_text(), std::string(kRs4simGsdFileName));
  return device;
}

}  // namespace rs4sim::gsd
