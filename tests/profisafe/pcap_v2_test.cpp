// V2 CRC2 against a real capture ([IEC 61784-3-3 CRC2], VERIFIED): a KUKA KRC4 F-device's
// PROFINET RT frames (tests/profisafe/data/seb711_krc4_profisafe_v2_status.pcap, kept with
// the test). The test parses the pcap itself.
//
// Encapsulation (found by exploration): pcap, link type 1 (Ethernet); PROFINET RT
// (EtherType 0x8892), Frame ID 0x8000 = the device's cyclic input frame. Its payload starts
// with three IOxS bytes of other submodules; the F-module's PDU follows at payload offset 3:
// 8 bytes F-input data, status byte, CRC2 (3 bytes). F_Par_CRC (CRC1) = 0x22FF.
// The virtual consecutive number (not sent) starts at 0 and advances whenever Toggle_d
// changes (one F-host cycle); the device may also change its data within one cycle (same
// VCN), and the bus repeats PDUs, so one PDU appears in several frames.
#include "profisafe/pdu.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::profisafe {
namespace {

using Bytes = std::vector<std::uint8_t>;

struct Pcap {
  bool swapped = false;
  std::uint32_t linktype = 0;
  std::vector<Bytes> packets;
};

std::uint32_t read32(const Bytes& b, std::size_t at, bool swapped) {
  std::uint32_t le = 0;
  for (std::size_t i = 4; i > 0; --i) le = (le << 8) | b[at + i - 1];
  return swapped ? __builtin_bswap32(le) : le;
}

// Classic libpcap format: 24-byte global header, 16-byte record headers.
std::optional<Pcap> read_pcap(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return std::nullopt;
  const Bytes b((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (b.size() < 24) return std::nullopt;
  Pcap p;
  const std::uint32_t magic = read32(b, 0, false);
  if (magic == 0xA1B2C3D4u || magic == 0xA1B23C4Du) {
    p.swapped = false;
  } else if (magic == 0xD4C3B2A1u || magic == 0x4D3CB2A1u) {
    p.swapped = true;
  } else {
    return std::nullopt;
  }
  p.linktype = read32(b, 20, p.swapped);
  std::size_t at = 24;
  while (at + 16 <= b.size()) {
    const std::uint32_t caplen = read32(b, at + 8, p.swapped);
    at += 16;
    if (caplen > b.size() - at) return std::nullopt;  // truncated record
    p.packets.emplace_back(b.begin() + static_cast<std::ptrdiff_t>(at),
                           b.begin() + static_cast<std::ptrdiff_t>(at + caplen));
    at += caplen;
  }
  return p;
}

constexpr std::size_t kPduOffset = 14 + 2 + 3;  // Ethernet header, Frame ID, 3 IOxS bytes
constexpr std::size_t kPduSize = 12;

std::vector<Bytes> device_pdus(const Pcap& p) {
  std::vector<Bytes> out;
  for (const Bytes& f : p.packets) {
    if (f.size() < kPduOffset + kPduSize) continue;
    if (f[12] != 0x88 || f[13] != 0x92) continue;  // PROFINET RT
    if (f[14] != 0x80 || f[15] != 0x00) continue;  // Frame ID 0x8000
    out.emplace_back(f.begin() + kPduOffset, f.begin() + kPduOffset + kPduSize);
  }
  return out;
}

bool toggled(const Bytes& before, const Bytes& after) {
  return ((before[8] ^ after[8]) & status_bit::kToggleD) != 0;
}

PduConfig capture_config() {
  PduConfig c;
  c.version = ProtocolVersion::kV2;
  c.data_size = 8;
  c.crc1 = 0x22FF;
  return c;
}

TEST(ProfisafePcapV2, All1809PdusOfTheCaptureCheck) {
  const auto pcap = read_pcap(RS4SIM_PROFISAFE_PCAP);
  ASSERT_TRUE(pcap) << "cannot read " << RS4SIM_PROFISAFE_PCAP;
  EXPECT_EQ(pcap->linktype, 1u);  // Ethernet
  const auto frames = device_pdus(*pcap);
  ASSERT_EQ(frames.size(), 5423u);

  const PduConfig c = capture_config();
  std::uint32_t vcn = 0;
  std::size_t distinct = 0, failures = 0;
  const Bytes* last = nullptr;
  for (const Bytes& pdu : frames) {
    if (last != nullptr && pdu == *last) continue;  // repeated cycle, same PDU
    if (last != nullptr && toggled(*last, pdu)) vcn = next_virtual_consecutive_number(vcn);
    last = &pdu;
    ++distinct;
    const auto r = check_pdu(c, pdu, vcn);
    if (!r.ok()) ++failures;
    // cons_nr_R only in the very first PDU.
    EXPECT_EQ((r.status_or_control & status_bit::kConsNrR) != 0, vcn == 0) << vcn;
  }
  EXPECT_EQ(distinct, 1809u);
  EXPECT_EQ(failures, 0u);
  EXPECT_GT(vcn, 1000u);  // the number really advanced through the capture
}

TEST(ProfisafePcapV2, RebuildsEveryPduByteForByte) {
  const auto pcap = read_pcap(RS4SIM_PROFISAFE_PCAP);
  ASSERT_TRUE(pcap);
  const PduConfig c = capture_config();
  std::uint32_t vcn = 0;
  const Bytes* last = nullptr;
  std::size_t rebuilt = 0;
  for (const Bytes& pdu : device_pdus(*pcap)) {
    if (last != nullptr && pdu == *last) continue;
    if (last != nullptr && toggled(*last, pdu)) vcn = next_virtual_consecutive_number(vcn);
    last = &pdu;
    std::array<std::uint8_t, kMaxPduSize> out{};
    const auto n = build_pdu(c, std::span(pdu).first(8), pdu[8], vcn, out);
    ASSERT_TRUE(n);
    ASSERT_EQ(Bytes(out.begin(), out.begin() + 12), pdu) << "vcn " << vcn;
    ++rebuilt;
  }
  EXPECT_EQ(rebuilt, 1809u);
}

TEST(ProfisafePcapV2, AWrongVirtualNumberFailsEveryPdu) {
  const auto pcap = read_pcap(RS4SIM_PROFISAFE_PCAP);
  ASSERT_TRUE(pcap);
  std::uint32_t vcn = 0;
  const Bytes* last = nullptr;
  for (const Bytes& pdu : device_pdus(*pcap)) {
    if (last != nullptr && pdu == *last) continue;
    if (last != nullptr && toggled(*last, pdu)) vcn = next_virtual_consecutive_number(vcn);
    last = &pdu;
    ASSERT_EQ(check_pdu(capture_config(), pdu, vcn + 1).error, ProfisafeError::kPduCrc2Mismatch)
        << vcn;
  }
}

}  // namespace
}  // namespace rs4sim::profisafe
