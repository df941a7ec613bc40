#include "rs4/rs232/rs232_codes.h"

namespace rs4sim::rs4::rs232 {

stream::LineSettings line_8n1(std::uint32_t baud) noexcept {
  return stream::LineSettings{baud, 8, stream::Parity::kNone, 1};
}

}  // namespace rs4sim::rs4::rs232
