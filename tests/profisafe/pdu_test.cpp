// Safety PDU build/check ([PROFIsafe V1.30 safety PDU] [IEC 61784-3-3 CRC2]).
// V2 known answers are the published VERIFIED vectors. V1 CRC2 is UNCERTAIN: its fixed bytes
// below were computed by an independent bitwise implementation of the candidate rule
// (and of each named variant), not by the code under test.
#include "profisafe/pdu.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rs4sim::profisafe {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes build(const PduConfig& c, const Bytes& data, std::uint8_t sc, std::uint32_t n) {
  std::array<std::uint8_t, kMaxPduSize> out{};
  const auto size = build_pdu(c, data, sc, n, out);
  EXPECT_TRUE(size) << size.error().message();
  return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(size ? size.value() : 0)};
}

PduConfig v2_config() {
  PduConfig c;
  c.version = ProtocolVersion::kV2;
  c.data_size = 8;
  c.crc1 = 0x22FF;
  return c;
}

TEST(ProfisafePduV2, SpecVector1) {
  const Bytes pdu{
      0x41, 0x01, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00,  // 0..7 F-input data
      0x40,                                            // 8 status: cons_nr_R
      0xBB, 0x5F, 0xB5,                                // 9 CRC2 (VCN 0), high first
  };
  EXPECT_EQ(build(v2_config(), Bytes(pdu.begin(), pdu.begin() + 8), 0x40, 0), pdu);
  const auto r = check_pdu(v2_config(), pdu, 0);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.status_or_control, 0x40);
  EXPECT_EQ(r.received_crc2, 0xBB5FB5u);
  EXPECT_EQ(check_pdu(v2_config(), pdu, 1).error,
            ProfisafeError::kPduCrc2Mismatch);  // VCN is covered
}

TEST(ProfisafePduV2, SpecVector2) {
  const Bytes pdu{
      0x41, 0x01, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00,  // 0..7 F-input data
      0x20,                                            // 8 status: Toggle_d
      0x81, 0x11, 0x99,                                // 9 CRC2 (VCN 1)
  };
  EXPECT_EQ(build(v2_config(), Bytes(pdu.begin(), pdu.begin() + 8), 0x20, 1), pdu);
  EXPECT_TRUE(check_pdu(v2_config(), pdu, 1).ok());
}

TEST(ProfisafePduV2, SpecVector3) {
  const Bytes pdu{
      0x41, 0x4D, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00,  // 0..7 F-input data
      0x00,                                            // 8 status
      0xE1, 0x8A, 0xA8,                                // 9 CRC2 (VCN 2)
  };
  EXPECT_EQ(build(v2_config(), Bytes(pdu.begin(), pdu.begin() + 8), 0x00, 2), pdu);
  EXPECT_TRUE(check_pdu(v2_config(), pdu, 2).ok());
}

PduConfig rs4_config(std::uint16_t crc1, bool check_seqnr) {
  PduConfig c;  // V1, 1 data byte, candidate variant
  c.crc1 = crc1;
  c.check_seqnr = check_seqnr;
  return c;
}

TEST(ProfisafePduV1, Rs4DevicePduCandidate) {
  // RS4 defaults: CRC1 0x83A9, F_Check_SeqNr 0.
  const Bytes pdu{
      0x80,        // 0 F-input data: OSSD on
      0x00,        // 1 status byte
      0x01,        // 2 consecutive number (not in CRC2)
      0x73, 0x0B,  // 3 CRC2 high, low
  };
  EXPECT_EQ(build(rs4_config(0x83A9, false), {0x80}, 0x00, 1), pdu);
  const auto r = check_pdu(rs4_config(0x83A9, false), pdu);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.data.size(), 1u);
  EXPECT_EQ(r.data[0], 0x80);
  EXPECT_EQ(r.consecutive_number, 1);
  // Not covered: another number keeps CRC2 valid (the driver compares the number).
  EXPECT_TRUE(check_pdu(rs4_config(0x83A9, false), Bytes{0x80, 0x00, 0x02, 0x73, 0x0B}).ok());
}

TEST(ProfisafePduV1, Rs4FailSafePdu) {
  const Bytes pdu{
      0x00,        // 0 F-input data: fail-safe value
      0x10,        // 1 status: FV_activated
      0x01,        // 2 consecutive number
      0x5B, 0xE3,  // 3 CRC2
  };
  EXPECT_EQ(build(rs4_config(0x83A9, false), {0x00}, status_bit::kFvActivated, 1), pdu);
}

TEST(ProfisafePduV1, SeqNrCoveredAndEveryVariant) {
  // F_Check_SeqNr 1 → CRC1 0xE850 (block 15 00 00 01 01 F8 00 0A).
  PduConfig c = rs4_config(0xE850, true);
  EXPECT_EQ(build(c, {0x41}, 0x00, 7), (Bytes{0x41, 0x00, 0x07, 0xF3, 0xF8}));
  EXPECT_EQ(check_pdu(c, Bytes{0x41, 0x00, 0x08, 0xF3, 0xF8}).error,
            ProfisafeError::kPduCrc2Mismatch);
  c.variant.order = Crc2Variant::Order::kForward;
  EXPECT_EQ(build(c, {0x41}, 0x00, 7), (Bytes{0x41, 0x00, 0x07, 0x69, 0x8C}));
  c.variant = {};
  c.variant.seq_position = Crc2Variant::SeqPosition::kLast;
  EXPECT_EQ(build(c, {0x41}, 0x00, 7), (Bytes{0x41, 0x00, 0x07, 0xB5, 0x72}));
  c.variant = {};
  c.variant.preset = Crc2Variant::Preset::kZero;
  EXPECT_EQ(build(c, {0x41}, 0x00, 7), (Bytes{0x41, 0x00, 0x07, 0xD2, 0x25}));
  c.variant = {};
  c.check_seqnr = false;
  c.variant.seq_coverage = Crc2Variant::SeqCoverage::kAlways;
  EXPECT_EQ(build(c, {0x41}, 0x00, 7), (Bytes{0x41, 0x00, 0x07, 0xF3, 0xF8}));
  c.check_seqnr = true;
  c.variant.seq_coverage = Crc2Variant::SeqCoverage::kNever;
  EXPECT_EQ(check_pdu(c, Bytes{0x41, 0x00, 0x08, 0xF3, 0xF8}).error,
            ProfisafeError::kPduCrc2Mismatch);
}

TEST(ProfisafePduV1, ThreeDataBytes) {
  PduConfig c = rs4_config(0x83A9, false);
  c.data_size = 3;
  const Bytes pdu{0x01, 0x02, 0x03,  // 0..2 F-data
                  0x10,              // 3 status/control
                  0xFF,              // 4 consecutive number 255
                  0xC9, 0x03};       // 5 CRC2
  EXPECT_EQ(build(c, {1, 2, 3}, 0x10, 255), pdu);
  EXPECT_TRUE(check_pdu(c, pdu).ok());
}

TEST(ProfisafePdu, WrongSizesAreTypedErrors) {
  const PduConfig c = rs4_config(0x83A9, false);
  for (std::size_t n : {0u, 1u, 4u, 6u, 100u}) {
    EXPECT_EQ(check_pdu(c, Bytes(n, 0)).error, ProfisafeError::kPduWrongSize) << n;
  }
  std::array<std::uint8_t, 4> small{};
  EXPECT_EQ(build_pdu(c, Bytes{1}, 0, 1, small).error(), ProfisafeError::kPduWrongSize);
  std::array<std::uint8_t, kMaxPduSize> out{};
  EXPECT_EQ(build_pdu(c, Bytes{1, 2}, 0, 1, out).error(), ProfisafeError::kPduWrongSize);
  PduConfig big = c;
  big.data_size = kMaxDataSize + 1;
  EXPECT_EQ(build_pdu(big, Bytes(kMaxDataSize + 1, 0), 0, 1, out).error(),
            ProfisafeError::kPduDataTooLong);
  EXPECT_EQ(check_pdu(big, Bytes(kMaxDataSize + 5, 0)).error, ProfisafeError::kPduWrongSize);
}

TEST(ProfisafePdu, CorruptedCrcReportsBothValues) {
  const auto r = check_pdu(rs4_config(0x83A9, false), Bytes{0x80, 0x00, 0x01, 0x73, 0x0A});
  EXPECT_EQ(r.error, ProfisafeError::kPduCrc2Mismatch);
  EXPECT_EQ(r.received_crc2, 0x730Au);
  EXPECT_EQ(r.computed_crc2, 0x730Bu);
}

TEST(ProfisafePdu, ConsecutiveNumberRanges) {
  EXPECT_EQ(next_consecutive_number(0), 1);
  EXPECT_EQ(next_consecutive_number(254), 255);
  EXPECT_EQ(next_consecutive_number(255), 1);
  EXPECT_EQ(previous_consecutive_number(1), 255);
  EXPECT_EQ(next_virtual_consecutive_number(0xFFFFFF), 1u);
  EXPECT_EQ(next_virtual_consecutive_number(5), 6u);
}

}  // namespace
}  // namespace rs4sim::profisafe

namespace rs4sim::profisafe {
namespace {

TEST(ProfisafeCrc2Variants, TwentyFourDistinctVariants) {
  const auto all = all_crc2_variants();
  EXPECT_EQ(all.size(), 24u);
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t j = i + 1; j < all.size(); ++j) EXPECT_NE(all[i], all[j]);
  }
}

TEST(ProfisafeCrc2Variants, ACaptureSettlesTheVariant) {
  // A pretend capture made with "forward, preset CRC1, number always covered, last".
  PduConfig c;
  c.crc1 = 0x83A9;
  c.variant = Crc2Variant{Crc2Variant::Order::kForward, Crc2Variant::Preset::kCrc1,
                          Crc2Variant::SeqCoverage::kAlways, Crc2Variant::SeqPosition::kLast};
  std::vector<std::array<std::uint8_t, kMaxPduSize>> pdus(20);
  std::vector<std::span<const std::uint8_t>> views;
  std::uint8_t n = 1;
  for (std::size_t i = 0; i < pdus.size(); ++i, n = next_consecutive_number(n)) {
    const std::array<std::uint8_t, 1> data{static_cast<std::uint8_t>(i * 13)};
    ASSERT_TRUE(build_pdu(c, data, static_cast<std::uint8_t>(i % 2 ? 0x10 : 0), n, pdus[i]));
    views.emplace_back(pdus[i].data(), 5);
  }
  PduConfig base;
  base.crc1 = 0x83A9;
  const auto found = matching_crc2_variants(base, views);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0], c.variant);
  base.crc1 = 0x83A8;  // a wrong CRC1 matches nothing
  EXPECT_TRUE(matching_crc2_variants(base, views).empty());
}

}  // namespace
}  // namespace rs4sim::profisafe
