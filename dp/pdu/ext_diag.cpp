// Extended diagnosis blocks, [IEC 61158-6-3 Slave_Diag]; alarm and status PDUs
// [IEC 61158-6-3 DPV1 alarms, status PDUs].
#include "dp/pdu/ext_diag.h"

#include "dp/pdu/wire.h"

namespace rs4sim::dp::pdu {
namespace {

constexpr std::uint8_t kMaxBlockLength = 63;  // 6-bit length incl. header
constexpr std::uint8_t kStatusBit = 0x80;

// [IEC 61158-6-3 DPV1 alarms]: 1…6 and 32…126 are defined; 0, 7…31 and 127 are reserved.
bool valid_alarm_type(std::uint8_t t) {
  return (t >= alarm_type::kDiagnostic && t <= alarm_type::kUpdate) ||
         (t >= alarm_type::kManufacturerMin && t <= alarm_type::kManufacturerMax);
}

// [IEC 61158-6-3 status PDUs]: 1, 2, 3, 30, 31 and 32…126 are defined.
bool valid_status_type(std::uint8_t t) {
  return (t >= 1 && t <= 3) || (t >= status_type::kPrmCmdAck && t <= 126);
}

// The bytes after the header byte: type, slot, specifier, data
// ([IEC 61158-6-3 DPV1 alarms, status PDUs]).
Result<ExtDiagBlock> decode_dpv1_block(std::span<const std::uint8_t> body) {
  codec::Reader r(body);
  const std::uint8_t type_byte = r.u8();
  const std::uint8_t slot = r.u8();
  const std::uint8_t spec = r.u8();
  if (!r.ok()) return PduError::kBadAlarm;
  const std::uint8_t type = type_byte & 0x7FU;
  if ((type_byte & kStatusBit) != 0) {
    if (!valid_status_type(type)) return PduError::kBadAlarm;
    return ExtDiagBlock{StatusPdu{type, slot, static_cast<StatusSpecifier>(spec & 0x03U),
                                  static_cast<std::uint8_t>(spec & 0xFCU), r.rest()}};
  }
  if (!valid_alarm_type(type)) return PduError::kBadAlarm;
  return ExtDiagBlock{AlarmPdu{type, slot, static_cast<std::uint8_t>(spec >> 3), wire::bit(spec, 2),
                               static_cast<AlarmSpecifier>(spec & 0x03U), r.rest()}};
}

// The block after its header byte h (kind in bits 7..6).
Result<ExtDiagBlock> decode_block(std::uint8_t h, bool dpv1, codec::Reader& in) {
  const unsigned kind = h >> 6U;
  if (kind == 2) {  // channel-related: fixed 3 bytes
    const std::uint8_t b1 = in.u8();
    const std::uint8_t b2 = in.u8();
    if (!in.ok()) return PduError::kBadDiagBlock;
    return ExtDiagBlock{
        ChannelDiag{static_cast<std::uint8_t>(h & 0x3FU), static_cast<ChannelDirection>(b1 >> 6),
                    static_cast<std::uint8_t>(b1 & 0x3FU), static_cast<std::uint8_t>(b2 >> 5),
                    static_cast<std::uint8_t>(b2 & 0x1FU)}};
  }
  if (kind == 3) return ExtDiagBlock{RevisionBlock{h}};  // revision / reserved: one byte
  const std::size_t len = h & 0x3FU;
  if (len < 2) return PduError::kBadDiagBlock;
  const auto body = in.bytes(len - 1);
  if (!in.ok()) return PduError::kBadDiagBlock;
  if (kind == 1) return ExtDiagBlock{IdentifierDiag{body}};
  if (dpv1) return decode_dpv1_block(body);
  return ExtDiagBlock{DeviceDiag{body}};
}

Result<void> append_block(std::uint8_t kind_bits, std::span<const std::uint8_t> head,
                          std::span<const std::uint8_t> data, fdl::DataUnit& out) {
  const std::size_t len = 1 + head.size() + data.size();
  if (len < 2 || len > kMaxBlockLength) return PduError::kValueOutOfRange;
  if (out.size() + len > wire::kMaxDpDu) return PduError::kTooLong;
  (void)wire::append(out, {static_cast<std::uint8_t>(kind_bits | len)});
  (void)wire::append(out, head);
  return wire::append(out, data);
}

}  // namespace

bool IdentifierDiag::has_diag(std::size_t identifier) const {
  const std::size_t byte = identifier / 8;
  return byte < bits.size() && ((bits[byte] >> (identifier % 8)) & 1U) != 0;
}

std::uint8_t AlarmPdu::specifier_byte() const {
  return static_cast<std::uint8_t>((static_cast<unsigned>(seq_nr) << 3) | wire::flag(add_ack, 2) |
                                   (static_cast<std::uint8_t>(specifier) & 0x03U));
}

Result<std::optional<ExtDiagBlock>> ExtDiagReader::next() {
  if (in_.at_end()) return std::optional<ExtDiagBlock>{};
  const std::uint8_t h = in_.u8();
  auto block = decode_block(h, dpv1_, in_);
  if (!block) {
    in_.fail();
    return block.error();
  }
  return std::optional<ExtDiagBlock>{block.value()};
}

Result<void> encode_device_diag(std::span<const std::uint8_t> data, fdl::DataUnit& out) {
  return append_block(0x00, {}, data, out);
}

Result<void> encode_identifier_diag(std::span<const std::uint8_t> bits, fdl::DataUnit& out) {
  return append_block(0x40, {}, bits, out);
}

Result<void> encode_channel_diag(const ChannelDiag& c, fdl::DataUnit& out) {
  if (c.identifier > 63 || c.channel > 63 || c.channel_type > 7 || c.error_type > 31 ||
      c.direction == ChannelDirection::kReserved || static_cast<unsigned>(c.direction) > 3) {
    return PduError::kValueOutOfRange;
  }
  return wire::append(
      out, {static_cast<std::uint8_t>(0x80U | c.identifier),
            static_cast<std::uint8_t>((static_cast<unsigned>(c.direction) << 6) | c.channel),
            static_cast<std::uint8_t>((c.channel_type << 5) | c.error_type)});
}

Result<void> encode_alarm(const AlarmPdu& a, fdl::DataUnit& out) {
  if (!valid_alarm_type(a.alarm_type) || a.seq_nr > 31 || static_cast<unsigned>(a.specifier) > 3) {
    return PduError::kValueOutOfRange;
  }
  const std::uint8_t head[3] = {a.alarm_type, a.slot, a.specifier_byte()};
  return append_block(0x00, head, a.data, out);
}

Result<void> encode_status(const StatusPdu& s, fdl::DataUnit& out) {
  if (!valid_status_type(s.status_type) || (s.specifier_reserved & 0x03U) != 0 ||
      static_cast<unsigned>(s.specifier) > 3) {
    return PduError::kValueOutOfRange;
  }
  const std::uint8_t head[3] = {
      static_cast<std::uint8_t>(kStatusBit | s.status_type), s.slot,
      static_cast<std::uint8_t>(s.specifier_reserved | static_cast<std::uint8_t>(s.specifier))};
  return append_block(0x00, head, s.data, out);
}

}  // namespace rs4sim::dp::pdu
