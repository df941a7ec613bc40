// I&M call header and I&M0 record, [IEC 61158-6-3 MSAC_C1].
#include "dp/pdu/im.h"

#include "codec/writer.h"
#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {

Result<ImCall> decode_im_call(std::span<const std::uint8_t> data) {
  if (data.size() < kImCallHeaderLength) return PduError::kTooShort;
  return ImCall{ImCallHeader{data[0], data[1], codec::be16(data[2], data[3])},
                data.subspan(kImCallHeaderLength)};
}

Result<void> encode_im_call(const ImCallHeader& h, fdl::DataUnit& out) {
  return wire::append(out, {h.extended_function, h.reserved, codec::high_byte(h.im_index),
                            codec::low_byte(h.im_index)});
}

Result<Im0> decode_im0(std::span<const std::uint8_t> record) {
  if (record.size() < kImRecordLength) return PduError::kTooShort;
  if (record.size() > kImRecordLength) return PduError::kTooLong;
  Im0 im;
  codec::Reader r(record);
  r.copy_to(im.header);
  im.manufacturer_id = r.u16_be();
  r.copy_to(im.order_id);
  r.copy_to(im.serial_number);
  im.hardware_revision = r.u16_be();
  r.copy_to(im.software_revision);
  im.revision_counter = r.u16_be();
  im.profile_id = r.u16_be();
  im.profile_specific_type = r.u16_be();
  r.copy_to(im.im_version);
  im.im_supported = r.u16_be();
  return im;
}

Result<void> encode_im0(const Im0& im, fdl::DataUnit& out) {
  if (out.size() + kImRecordLength > wire::kMaxDpDu) return PduError::kTooLong;
  codec::Appender w(out, wire::kMaxDpDu);
  w.copy_from(im.header);
  w.u16_be(im.manufacturer_id);
  w.copy_from(im.order_id);
  w.copy_from(im.serial_number);
  w.u16_be(im.hardware_revision);
  w.copy_from(im.software_revision);
  w.u16_be(im.revision_counter);
  w.u16_be(im.profile_id);
  w.u16_be(im.profile_specific_type);
  w.copy_from(im.im_version);
  w.u16_be(im.im_supported);
  return boost::outcome_v2::success();
}

}  // namespace rs4sim::dp::pdu
