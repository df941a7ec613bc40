// libFuzzer target: the safety PDU checker (profisafe/pdu.h). Byte 0 selects the
// configuration (version, F_Check_SeqNr, CRC2 variant), bytes 1..2 the CRC1, byte 3 the data
// size (mod 16: 0 and 13..15 are refused configurations), bytes 4..5 the V2 virtual number;
// the rest is the PDU. Invariants: never crash; a PDU that checks
// is rebuilt byte for byte.
#include "profisafe/pdu.h"

#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::profisafe;
  if (size < 6) return 0;
  const std::uint8_t sel = data[0];
  PduConfig c;
  c.version = (sel & 0x01) != 0 ? ProtocolVersion::kV2 : ProtocolVersion::kV1;
  c.check_seqnr = (sel & 0x02) != 0;
  c.variant.order =
      (sel & 0x04) != 0 ? Crc2Variant::Order::kForward : Crc2Variant::Order::kReversed;
  c.variant.seq_position =
      (sel & 0x08) != 0 ? Crc2Variant::SeqPosition::kLast : Crc2Variant::SeqPosition::kFirst;
  c.variant.preset = (sel & 0x10) != 0 ? Crc2Variant::Preset::kZero : Crc2Variant::Preset::kCrc1;
  c.crc1 = static_cast<std::uint16_t>((data[1] << 8) | data[2]);
  c.data_size = data[3] % 16u;
  const std::uint32_t vcn = static_cast<std::uint32_t>((data[4] << 8) | data[5]);
  const std::span<const std::uint8_t> pdu(data + 6, size - 6);
  const PduCheck r = check_pdu(c, pdu, vcn);
  if (!r.ok()) return 0;
  if (r.data.size() != c.data_size || pdu.size() != pdu_size(c)) std::abort();
  std::array<std::uint8_t, kMaxPduSize> out{};
  const std::uint32_t number = c.version == ProtocolVersion::kV1 ? r.consecutive_number : vcn;
  const auto n = build_pdu(c, r.data, r.status_or_control, number, out);
  if (!n || n.value() != pdu.size() || std::memcmp(out.data(), pdu.data(), pdu.size()) != 0)
    std::abort();
  return 0;
}
