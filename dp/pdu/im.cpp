// I&M call header and I&M0 record, spec/profibus-dp.md §3.3.
#include "dp/pdu/im.h"

#include "dp/pdu/wire.h"

#include <algorithm>

namespace rs4sim::dp::pdu {
namespace {

// Reads big-endian fields in order.
class Cursor {
 public:
  explicit Cursor(std::span<const std::uint8_t> b) : b_(b) {}
  std::uint16_t u16() {
    const auto v = wire::be16(b_[pos_], b_[pos_ + 1]);
    pos_ += 2;
    return v;
  }
  template <class T, std::size_t N>
  void bytes(std::array<T, N>& out) {
    std::transform(b_.begin() + static_cast<std::ptrdiff_t>(pos_),
                   b_.begin() + static_cast<std::ptrdiff_t>(pos_ + N), out.begin(),
                   [](std::uint8_t c) { return static_cast<T>(c); });
    pos_ += N;
  }

 private:
  std::span<const std::uint8_t> b_;
  std::size_t pos_ = 0;
};

template <class T, std::size_t N>
void put(fdl::DataUnit& out, const std::array<T, N>& a) {
  for (const T c : a) out.push_back(static_cast<std::uint8_t>(c));
}

void put16(fdl::DataUnit& out, std::uint16_t v) {
  out.push_back(wire::hi(v));
  out.push_back(wire::lo(v));
}

}  // namespace

Result<ImCall> decode_im_call(std::span<const std::uint8_t> data) {
  if (data.size() < kImCallHeaderLength) return PduError::kTooShort;
  return ImCall{ImCallHeader{data[0], data[1], wire::be16(data[2], data[3])},
                data.subspan(kImCallHeaderLength)};
}

Result<void> encode_im_call(const ImCallHeader& h, fdl::DataUnit& out) {
  return wire::append(out, {h.extended_function, h.reserved, wire::hi(h.im_index), wire::lo(h.im_index)});
}

Result<Im0> decode_im0(std::span<const std::uint8_t> record) {
  if (record.size() < kImRecordLength) return PduError::kTooShort;
  if (record.size() > kImRecordLength) return PduError::kTooLong;
  Im0 im;
  Cursor c(record);
  c.bytes(im.header);
  im.manufacturer_id = c.u16();
  c.bytes(im.order_id);
  c.bytes(im.serial_number);
  im.hardware_revision = c.u16();
  c.bytes(im.software_revision);
  im.revision_counter = c.u16();
  im.profile_id = c.u16();
  im.profile_specific_type = c.u16();
  c.bytes(im.im_version);
  im.im_supported = c.u16();
  return im;
}

Result<void> encode_im0(const Im0& im, fdl::DataUnit& out) {
  if (out.size() + kImRecordLength > wire::kMaxDpDu) return PduError::kTooLong;
  put(out, im.header);
  put16(out, im.manufacturer_id);
  put(out, im.order_id);
  put(out, im.serial_number);
  put16(out, im.hardware_revision);
  put(out, im.software_revision);
  put16(out, im.revision_counter);
  put16(out, im.profile_id);
  put16(out, im.profile_specific_type);
  put(out, im.im_version);
  put16(out, im.im_supported);
  return boost::outcome_v2::success();
}

}  // namespace rs4sim::dp::pdu
