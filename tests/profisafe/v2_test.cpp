// PROFIsafe V2 in the drivers ([IEC 61784-3-3 safety PDU, F-Parameters]; docs/profisafe.md):
// R_cons_nr / cons_nr_R, Toggle_h / Toggle_d, the virtual consecutive number inside CRC2, the
// 4-byte CRC2 against a bitwise CRC-32 written here, the watchdog on injected time, and the
// standard F-parameter diagnosis 64..71. Host PDUs are built with build_pdu, not by FHost.
#include "profisafe/f_device.h"
#include "profisafe/f_host.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace rs4sim::profisafe {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

const TimePoint kStart{std::chrono::hours(1)};

// SIL 3, V2, source 1, destination 1, 150 ms (the AS-i F-Link module's defaults), with the given
// CRC2 length.
FParameters v2_parameters(CrcLength crc_length = CrcLength::k3Byte) {
  FParameters p = parse_f_parameters(Bytes{0x08, 0x40, 0x00, 0x01, 0x00, 0x01, 0x00, 0x96, 0xBB,
                                           0x95})
                      .value();
  p.crc_length = crc_length;
  p.par_crc = crc1(p);
  return p;
}

DeviceProfile v2_profile(CrcLength crc_length = CrcLength::k3Byte) {
  return profile_for(v2_parameters(crc_length));
}

class ProfisafeV2Device : public ::testing::Test {
 protected:
  ProfisafeV2Device() : dev_(FDeviceConfig{v2_profile(), 2, {}}) {
    const auto block = encode_f_parameters(v2_parameters());
    EXPECT_TRUE(dev_.set_parameters(block).ok());
    host_ = PduConfig::from(parse_f_parameters(block).value(), 2);
    const std::array<std::uint8_t, 2> in{0xA5, 0x0F};
    dev_.set_input(in);
  }
  Bytes host_pdu(std::uint8_t control, std::uint32_t vcn, std::uint8_t data = 0x11) const {
    std::array<std::uint8_t, kMaxPduSize> out{};
    const auto size = build_pdu(host_, Bytes{data, 0x22}, control, vcn, out);
    return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(size.value())};
  }
  // The device's answer, checked as the host checks it with the given virtual number.
  PduCheck answer(std::uint32_t vcn) {
    const auto r = dev_.response();
    answer_.assign(r.begin(), r.end());
    return check_pdu(host_, answer_, vcn);
  }

  FDevice dev_;
  PduConfig host_{};
  Bytes answer_;
};

constexpr auto kReset = control_bit::kRConsNr;
constexpr auto kToggle = control_bit::kToggleH;

TEST_F(ProfisafeV2Device, RConsNrIsAnsweredWithConsNrRThenToggleDFollowsToggleH) {
  EXPECT_EQ(dev_.on_pdu(host_pdu(kReset, 0), kStart), FDeviceEvent::kNew);
  auto a = answer(0);
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(answer_.size(), 6u);  // 2 data + status + 3-byte CRC2, no number sent
  EXPECT_EQ(a.status_or_control, status_bit::kConsNrR);  // Toggle_d 0 = Toggle_h 0
  EXPECT_EQ(Bytes(a.data.begin(), a.data.end()), (Bytes{0xA5, 0x0F}));
  EXPECT_EQ(dev_.on_pdu(host_pdu(kToggle, 1, 0x33), kStart + 10ms), FDeviceEvent::kNew);
  a = answer(1);
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(a.status_or_control, status_bit::kToggleD);
  EXPECT_EQ(dev_.output()[0], 0x33);
  EXPECT_EQ(dev_.last_number(), 1u);
  // The same Toggle_h again: a repeat of number 1, nothing changes.
  EXPECT_EQ(dev_.on_pdu(host_pdu(kToggle, 1, 0x44), kStart + 20ms), FDeviceEvent::kRepeat);
  EXPECT_EQ(dev_.output()[0], 0x33);
  EXPECT_EQ(dev_.on_pdu(host_pdu(0, 2), kStart + 30ms), FDeviceEvent::kNew);
  EXPECT_TRUE(answer(2).ok());
  EXPECT_FALSE(answer(1).ok());  // the answer's CRC2 runs over the virtual number 2
}

TEST_F(ProfisafeV2Device, ASkippedVirtualNumberIsANumberFaultTheHostSees) {
  ASSERT_EQ(dev_.on_pdu(host_pdu(kReset, 0), kStart), FDeviceEvent::kNew);
  ASSERT_EQ(dev_.on_pdu(host_pdu(kToggle, 1), kStart + 10ms), FDeviceEvent::kNew);
  // Toggle_h flips but the PDU's CRC2 runs over 3, not 2.
  EXPECT_EQ(dev_.on_pdu(host_pdu(0, 3), kStart + 20ms), FDeviceEvent::kNumberError);
  EXPECT_EQ(dev_.counters().number_errors, 1u);
  EXPECT_EQ(dev_.output()[0], 0);  // fail-safe at once
  const auto a = answer(3);       // answered over the host's number: the host sees CE_CRC
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(a.status_or_control, status_bit::kCeCrc | status_bit::kFvActivated);
  EXPECT_EQ(Bytes(a.data.begin(), a.data.end()), (Bytes{0, 0}));  // fail-safe values
}

TEST_F(ProfisafeV2Device, AGarbledPduIsACrc2FaultNeverACrash) {
  ASSERT_EQ(dev_.on_pdu(host_pdu(kReset, 0), kStart), FDeviceEvent::kNew);
  Bytes garbled = host_pdu(kToggle, 1);
  garbled[1] ^= 0x40;
  EXPECT_EQ(dev_.on_pdu(garbled, kStart + 10ms), FDeviceEvent::kCrcError);
  EXPECT_EQ(dev_.on_pdu(Bytes{1, 2, 3}, kStart + 20ms), FDeviceEvent::kCrcError);
  EXPECT_EQ(dev_.on_pdu(Bytes{}, kStart + 30ms), FDeviceEvent::kCrcError);
  EXPECT_EQ(dev_.counters().crc_errors, 3u);
  EXPECT_EQ(dev_.state(), FDeviceState::kFault);
  EXPECT_NE(dev_.status_byte() & status_bit::kCeCrc, 0);
}

// F_WD_Time 150 ms from the last valid new PDU; a repeat does not restart it.
TEST_F(ProfisafeV2Device, WatchdogOnTheInjectedClockBothSidesOfTheBound) {
  ASSERT_EQ(dev_.on_pdu(host_pdu(kReset, 0), kStart), FDeviceEvent::kNew);
  ASSERT_EQ(dev_.on_pdu(host_pdu(kToggle, 1), kStart + 50ms), FDeviceEvent::kNew);
  ASSERT_EQ(dev_.on_pdu(host_pdu(kToggle, 1), kStart + 100ms), FDeviceEvent::kRepeat);
  EXPECT_EQ(dev_.next_deadline(), kStart + 200ms);
  dev_.on_time(kStart + 199ms);
  EXPECT_EQ(dev_.state(), FDeviceState::kRun);
  dev_.on_time(kStart + 200ms);
  EXPECT_EQ(dev_.state(), FDeviceState::kFault);
  EXPECT_EQ(dev_.counters().watchdog_timeouts, 1u);
  EXPECT_NE(dev_.status_byte() & status_bit::kWdTimeout, 0);
}

// CRC-32 of [IEC 61784-3-3 CRC2] written here bit by bit: poly 0xF4ACFB13, MSB first, preset
// CRC1, over the reverse of [virtual number, 4 bytes big-endian] + F-data + status/control.
std::uint32_t reference_crc32(std::uint16_t crc1, const Bytes& data, std::uint8_t status,
                              std::uint32_t vcn) {
  Bytes seq{static_cast<std::uint8_t>(vcn >> 24), static_cast<std::uint8_t>(vcn >> 16),
            static_cast<std::uint8_t>(vcn >> 8), static_cast<std::uint8_t>(vcn)};
  seq.insert(seq.end(), data.begin(), data.end());
  seq.push_back(status);
  std::uint32_t reg = crc1;
  for (auto it = seq.rbegin(); it != seq.rend(); ++it) {
    reg ^= static_cast<std::uint32_t>(*it) << 24;
    for (int i = 0; i < 8; ++i) reg = (reg & 0x80000000u) != 0 ? (reg << 1) ^ 0xF4ACFB13u : reg << 1;
  }
  return reg;
}

TEST(ProfisafeV2Crc32, FourByteCrc2AgreesWithABitwiseCrc32) {
  const FParameters p = v2_parameters(CrcLength::k4Byte);
  const PduConfig c = PduConfig::from(p, 3);
  EXPECT_TRUE(c.long_crc2);
  EXPECT_EQ(pdu_size(c), 8u);  // 3 data + status + 4-byte CRC2
  const Bytes data{0x01, 0x80, 0xFE};
  for (const std::uint32_t vcn : {0u, 1u, 0x123456u, 0xFFFFFFu}) {
    std::array<std::uint8_t, kMaxPduSize> out{};
    ASSERT_TRUE(build_pdu(c, data, 0x24, vcn, out));
    const std::uint32_t expected = reference_crc32(crc1(p), data, 0x24, vcn);
    EXPECT_EQ(Bytes(out.begin() + 4, out.begin() + 8),
              (Bytes{static_cast<std::uint8_t>(expected >> 24),
                     static_cast<std::uint8_t>(expected >> 16),
                     static_cast<std::uint8_t>(expected >> 8), static_cast<std::uint8_t>(expected)}))
        << vcn;
  }
}

// [IEC 61784-3-3 F-Parameters]: the standard diagnosis of each refused F-parameter block.
TEST(ProfisafeV2Diagnosis, EachRefusedFParameterGivesItsStandardCode) {
  struct DiagnosisCase {
    const char* what;
    void (*change)(FParameters&, DeviceProfile&);
    std::uint8_t code;
  };
  const std::vector<DiagnosisCase> cases = {
      {"accepted", [](FParameters&, DeviceProfile&) {}, 0},
      {"F_Dest_Add mismatch", [](FParameters& p, DeviceProfile&) { p.dest_add = 2; }, 64},
      {"own F_Dest_Add invalid", [](FParameters&, DeviceProfile& d) { d.dest_add = 0; }, 65},
      {"F_Source_Add 0", [](FParameters& p, DeviceProfile&) { p.source_add = 0; }, 66},
      {"F_WD_Time 5", [](FParameters& p, DeviceProfile&) { p.wd_time_ms = 5; }, 67},
      {"SIL 2", [](FParameters& p, DeviceProfile&) { p.sil = Sil::kSil2; }, 68},
      {"4-byte CRC2", [](FParameters& p, DeviceProfile&) { p.crc_length = CrcLength::k4Byte; },
       69},
      {"F_Block_ID 1", [](FParameters& p, DeviceProfile&) { p.block_id = 1; }, 70},
  };
  for (const auto& c : cases) {
    FParameters p = v2_parameters();
    DeviceProfile d = v2_profile();
    c.change(p, d);
    FDevice dev(FDeviceConfig{d, 1, {}});
    (void)dev.set_parameters(encode_f_parameters(p));
    EXPECT_EQ(dev.diagnosis(), c.code) << c.what;
    EXPECT_EQ(dev.state() == FDeviceState::kStartup, c.code == 0) << c.what;
  }
  FParameters p = v2_parameters();
  p.par_crc = 0x1234;  // a wrong F_Par_CRC
  FDevice dev(FDeviceConfig{v2_profile(), 1, {}});
  (void)dev.set_parameters(encode_f_parameters_raw(p));
  EXPECT_EQ(dev.diagnosis(), 71);
  for (std::uint8_t code = 64; code <= 71; ++code)
    EXPECT_NE(std::string(standard_diagnosis_text(code)), "") << int{code};
  EXPECT_EQ(std::string(standard_diagnosis_text(72)), "");
}

// The F-host's V2 start: number 0 with R_cons_nr and Toggle_h 0, then Toggle_h flips per new PDU.
TEST(ProfisafeV2Host, StartsWithRConsNrAndFlipsToggleH) {
  FHost host(FHostConfig{v2_parameters(), 1, {}});
  FDevice dev(FDeviceConfig{v2_profile(), 1, {}});
  ASSERT_TRUE(dev.set_parameters(host.parameter_block()).ok());
  TimePoint now = kStart;
  std::vector<std::uint8_t> controls;
  for (int i = 0; i < 4; ++i) {
    now += 10ms;
    const auto req = host.request(now);
    controls.push_back(req[1]);
    ASSERT_EQ(dev.on_pdu(req, now), FDeviceEvent::kNew);
    ASSERT_EQ(host.on_pdu(dev.response(), now), FHostEvent::kValid);
    EXPECT_EQ(host.number(), static_cast<std::uint32_t>(i));
  }
  // activate_FV while starting up, then the toggles alone.
  EXPECT_EQ(controls, (std::vector<std::uint8_t>{kReset | control_bit::kActivateFv, kToggle, 0,
                                                 kToggle}));
}

TEST(ProfisafeV2Config, AcceptsV1AndV2CombinationsOnly) {
  FDeviceConfig c{v2_profile(CrcLength::k4Byte), 1, {}};
  EXPECT_NO_THROW(FDevice{c});
  c.profile.crc_length = CrcLength::k2Byte;  // V2 never uses the 2-byte CRC2
  EXPECT_THROW(FDevice{c}, std::invalid_argument);
  FHostConfig h{v2_parameters(), 1, {}};
  EXPECT_NO_THROW(FHost{h});
  h.params.par_version = 0;  // V1 with a 3-byte CRC2
  EXPECT_THROW(FHost{h}, std::invalid_argument);
}

}  // namespace
}  // namespace rs4sim::profisafe
