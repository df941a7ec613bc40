// V2 CRC2 against a real capture ([IEC 61784-3-3 CRC2], VERIFIED): a KUKA KRC4 F-device's
// PROFINET RT frames, read at run time where capture.h says (skipped when absent). The test
// parses the pcap itself.
//
// Encapsulation (found by exploration): pcap, link type 1 (Ethernet); PROFINET RT
// (EtherType 0x8892), Frame ID 0x8000 = the device's cyclic input frame. Its payload starts
// with three IOxS bytes of other submodules; the F-module's PDU follows at payload offset 3:
// 8 bytes F-input data, status byte, CRC2 (3 bytes). F_Par_CRC (CRC1) = 0x22FF.
// The virtual consecutive number (not sent) starts at 0 and advances whenever Toggle_d
// changes (one F-host cycle); the device may also change its data within one cycle (same
// VCN), and the bus repeats PDUs, so one PDU appears in several frames.
#include "capture.h"
#include "profisafe/f_device.h"
#include "profisafe/f_host.h"
#include "profisafe/pdu.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
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

// The capture, nullopt when it is absent (the test skips); an unreadable file gives an empty
// Pcap, which fails the tests' counts.
std::optional<Pcap> load_capture() {
  const auto path = testing::profisafe_capture();
  if (!path) return std::nullopt;
  return read_pcap(path->string()).value_or(Pcap{});
}
#define RS4SIM_SKIP_WITHOUT_CAPTURE(pcap) \
  if (!(pcap)) GTEST_SKIP() << "the real capture is absent: " << testing::kProfisafeV2Capture

// The distinct device PDUs in order (a PDU repeated by the bus is one), each with its virtual
// consecutive number: 0 first, + 1 whenever Toggle_d changes (one F-host cycle).
struct Step {
  const Bytes* pdu = nullptr;
  std::uint32_t vcn = 0;
  bool new_cycle = false;  // Toggle_d changed (or the first PDU)
};
std::vector<Step> distinct_steps(const std::vector<Bytes>& frames) {
  std::vector<Step> out;
  for (const Bytes& pdu : frames) {
    if (!out.empty() && pdu == *out.back().pdu) continue;
    const bool fresh = out.empty() || toggled(*out.back().pdu, pdu);
    const std::uint32_t vcn =
        out.empty() ? 0
                    : (fresh ? next_virtual_consecutive_number(out.back().vcn) : out.back().vcn);
    out.push_back({&pdu, vcn, fresh});
  }
  return out;
}

// F-parameters whose CRC1 is the capture's 0x22FF (its own are not in the capture; CRC2 depends
// on CRC1 alone): SIL3, 3-byte CRC2, V2, F_Source_Add 1, F_Dest_Add 9, F_WD_Time 171 ms, found by
// a search over F_Dest_Add and F_WD_Time with an independent CRC1.
FParameters capture_parameters() {
  return parse_f_parameters(Bytes{0x08, 0x40, 0x00, 0x01, 0x00, 0x09, 0x00, 0xAB, 0x22, 0xFF})
      .value();
}

// The capture's PDUs: V2, 8 bytes F-data, 3-byte CRC2, CRC1 0x22FF.
PduConfig capture_config() { return PduConfig::from(capture_parameters(), 8); }

TEST(ProfisafePcapV2, All1809PdusOfTheCaptureCheck) {
  const auto pcap = load_capture();
  RS4SIM_SKIP_WITHOUT_CAPTURE(pcap);
  EXPECT_EQ(pcap->linktype, 1u);  // Ethernet
  const auto frames = device_pdus(*pcap);
  ASSERT_EQ(frames.size(), 5423u);
  const auto steps = distinct_steps(frames);
  std::size_t failures = 0;
  for (const Step& s : steps) {
    const auto r = check_pdu(capture_config(), *s.pdu, s.vcn);
    if (!r.ok()) ++failures;
    // cons_nr_R only in the very first PDU.
    EXPECT_EQ((r.status_or_control & status_bit::kConsNrR) != 0, s.vcn == 0) << s.vcn;
  }
  EXPECT_EQ(steps.size(), 1809u);
  EXPECT_EQ(failures, 0u);
  EXPECT_GT(steps.back().vcn, 1000u);  // the number really advanced through the capture
}

TEST(ProfisafePcapV2, RebuildsEveryPduByteForByte) {
  const auto pcap = load_capture();
  RS4SIM_SKIP_WITHOUT_CAPTURE(pcap);
  std::size_t rebuilt = 0;
  const auto frames = device_pdus(*pcap);  // the steps point into it
  for (const Step& s : distinct_steps(frames)) {
    const Bytes& pdu = *s.pdu;
    std::array<std::uint8_t, kMaxPduSize> out{};
    const auto n = build_pdu(capture_config(), std::span(pdu).first(8), pdu[8], s.vcn, out);
    ASSERT_TRUE(n);
    ASSERT_EQ(Bytes(out.begin(), out.begin() + 12), pdu) << "vcn " << s.vcn;
    ++rebuilt;
  }
  EXPECT_EQ(rebuilt, 1809u);
}

TEST(ProfisafePcapV2, AWrongVirtualNumberFailsEveryPdu) {
  const auto pcap = load_capture();
  RS4SIM_SKIP_WITHOUT_CAPTURE(pcap);
  const auto frames = device_pdus(*pcap);  // the steps point into it
  for (const Step& s : distinct_steps(frames)) {
    ASSERT_EQ(check_pdu(capture_config(), *s.pdu, s.vcn + 1).error,
              ProfisafeError::kPduCrc2Mismatch)
        << s.vcn;
  }
}

// Our F-device in V2, fed host PDUs of the F-host's rule (R_cons_nr with number 0 first, Toggle_h
// flipped per new cycle) and the capture's F-input data, sends every distinct PDU of the real
// device byte for byte: data, status (cons_nr_R first, then Toggle_d), CRC2 over the virtual
// number.
TEST(ProfisafePcapV2, OurFDeviceSendsTheCapturedPdusByteForByte) {
  const auto pcap = load_capture();
  RS4SIM_SKIP_WITHOUT_CAPTURE(pcap);
  const FParameters p = capture_parameters();
  ASSERT_EQ(crc1(p), 0x22FF);
  FDevice dev(FDeviceConfig{profile_for(p), 8, {}});
  ASSERT_TRUE(dev.set_parameters(encode_f_parameters(p)).ok());
  TimePoint now{std::chrono::hours(1)};
  std::size_t matched = 0;
  const auto frames = device_pdus(*pcap);  // the steps point into it
  for (const Step& s : distinct_steps(frames)) {
    const Bytes& pdu = *s.pdu;
    if (s.new_cycle) {
      const bool toggle = (pdu[8] & status_bit::kToggleD) != 0;
      const auto control = static_cast<std::uint8_t>((toggle ? control_bit::kToggleH : 0) |
                                                      (s.vcn == 0 ? control_bit::kRConsNr : 0));
      std::array<std::uint8_t, kMaxPduSize> out{};
      const auto n = build_pdu(capture_config(), Bytes(8, 0), control, s.vcn, out);
      ASSERT_TRUE(n);
      now += std::chrono::milliseconds(10);
      ASSERT_EQ(dev.on_pdu(std::span(out).first(n.value()), now), FDeviceEvent::kNew) << s.vcn;
    }
    dev.set_input(std::span(pdu).first(8));
    const auto r = dev.response();
    ASSERT_EQ(Bytes(r.begin(), r.end()), pdu) << "vcn " << s.vcn;
    ++matched;
  }
  EXPECT_EQ(matched, 1809u);
}

// Our F-host in V2 takes the first PDU of each cycle of the capture as the valid answer to its
// own request (same virtual number, Toggle_d = its Toggle_h) and passes the data through.
TEST(ProfisafePcapV2, OurFHostAcceptsEveryCycleOfTheCapture) {
  const auto pcap = load_capture();
  RS4SIM_SKIP_WITHOUT_CAPTURE(pcap);
  FHost host(FHostConfig{capture_parameters(), 8, {}});
  ASSERT_EQ(host.crc1(), 0x22FF);
  TimePoint now{std::chrono::hours(1)};
  std::size_t cycles = 0;
  const auto frames = device_pdus(*pcap);  // the steps point into it
  for (const Step& s : distinct_steps(frames)) {
    if (!s.new_cycle) continue;
    now += std::chrono::milliseconds(10);
    const auto request = host.request(now);
    ASSERT_EQ(request.size(), 12u);
    EXPECT_EQ((request[8] & control_bit::kRConsNr) != 0, s.vcn == 0);
    ASSERT_EQ(host.on_pdu(*s.pdu, now), FHostEvent::kValid) << s.vcn;
    EXPECT_EQ(host.number(), s.vcn);
    ++cycles;
  }
  EXPECT_EQ(host.state(), FHostState::kRun);
  EXPECT_EQ(host.counters().passivations, 0u);
  EXPECT_GT(cycles, 1000u);
}

}  // namespace
}  // namespace rs4sim::profisafe
