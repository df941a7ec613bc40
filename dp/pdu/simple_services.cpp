// Empty requests and I/O images,
// [IEC 61158-6-3 SAP assignment, Set_Slave_Add, Rd_Inp/Rd_Outp, Data_Exchange].
#include "dp/pdu/simple_services.h"

#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {

Result<void> decode_empty_request(std::span<const std::uint8_t> du) {
  if (!du.empty()) return PduError::kNotEmpty;
  return boost::outcome_v2::success();
}

Result<void> encode_io_image(std::span<const std::uint8_t> image, fdl::DataUnit& out) {
  if (image.size() > kMaxIoLength) return PduError::kTooLong;
  return wire::append(out, image);
}

Result<std::span<const std::uint8_t>> decode_io_image(std::span<const std::uint8_t> du) {
  if (du.size() > kMaxIoLength) return PduError::kTooLong;
  return du;
}

}  // namespace rs4sim::dp::pdu
