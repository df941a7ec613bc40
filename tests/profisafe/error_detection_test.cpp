// Error detection of the RS4's 5-byte V1 PDUs
// ([docs/profisafe.md#error-detection-measured-by-error_detection_testcpp]), exhaustively over all
// positions, for both directions, F_Check_SeqNr 0 and 1, and every named Crc2Variant.
//
// A corrupted PDU counts as detected when the receiver does not accept it as the expected
// PDU: CRC2 (or size) fails, or the consecutive number is not the expected one (the F-host
// compares the echo; the F-device discards a repeat and faults on any other number).
// Findings (printed, see docs/profisafe.md): with CRC-16 0x4EAB every 1..5-bit error is
// detected for all variants; the first undetected patterns have weight 6.
#include "profisafe/pdu.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace rs4sim::profisafe {
namespace {

constexpr unsigned kBits = 40;  // 5 bytes

struct Case {
  std::string name;
  PduConfig config;
  std::uint8_t data, sc, number;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  const std::array<Crc2Variant::Order, 2> orders{Crc2Variant::Order::kReversed,
                                                 Crc2Variant::Order::kForward};
  const std::array<Crc2Variant::SeqPosition, 2> positions{Crc2Variant::SeqPosition::kFirst,
                                                          Crc2Variant::SeqPosition::kLast};
  const std::array<Crc2Variant::Preset, 2> presets{Crc2Variant::Preset::kCrc1,
                                                   Crc2Variant::Preset::kZero};
  for (bool seq : {false, true}) {
    for (auto order : orders) {
      for (auto pos : positions) {
        for (auto preset : presets) {
          PduConfig c;
          c.check_seqnr = seq;
          c.crc1 = seq ? 0xE850 : 0x83A9;  // RS4 defaults with F_Check_SeqNr 1 / 0
          c.variant.order = order;
          c.variant.seq_position = pos;
          c.variant.preset = preset;
          const std::string n = std::string("seqnr") + (seq ? "1 " : "0 ") + to_string(order) +
                                " " + to_string(pos) + " " + to_string(preset);
          out.push_back({n + " device->host", c, 0x80, status_bit::kFvActivated, 17});
          out.push_back({n + " host->device", c, 0x41, control_bit::kActivateFv, 200});
        }
      }
    }
  }
  return out;
}

std::uint64_t to_bits(const std::array<std::uint8_t, 5>& b) {
  std::uint64_t v = 0;
  for (std::uint8_t x : b) v = (v << 8) | x;
  return v;
}
std::array<std::uint8_t, 5> to_bytes(std::uint64_t v) {
  std::array<std::uint8_t, 5> b{};
  for (int i = 4; i >= 0; --i, v >>= 8)
    b[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v);
  return b;
}

bool accepted(const Case& c, std::uint64_t bits) {
  const auto b = to_bytes(bits);
  const PduCheck r = check_pdu(c.config, b);
  return r.ok() && r.consecutive_number == c.number;
}

// Number of undetected error patterns of exactly `weight` bits (all C(40, weight) positions).
std::uint64_t undetected(const Case& c, std::uint64_t pdu, unsigned weight, unsigned from = 0,
                         std::uint64_t pattern = 0) {
  if (weight == 0) return pattern != 0 && accepted(c, pdu ^ pattern) ? 1 : 0;
  std::uint64_t n = 0;
  for (unsigned i = from; i + weight <= kBits; ++i)
    n += undetected(c, pdu, weight - 1, i + 1, pattern | (1ull << i));
  return n;
}

std::uint64_t build_bits(const Case& c) {
  std::array<std::uint8_t, kMaxPduSize> out{};
  const std::array<std::uint8_t, 1> data{c.data};
  EXPECT_TRUE(build_pdu(c.config, data, c.sc, c.number, out));
  return to_bits({out[0], out[1], out[2], out[3], out[4]});
}

TEST(ProfisafeErrorDetection, EveryOneToFourBitErrorIsDetected) {
  for (const Case& c : cases()) {
    const std::uint64_t pdu = build_bits(c);
    ASSERT_TRUE(accepted(c, pdu)) << c.name;  // the intact PDU is accepted
    for (unsigned w = 1; w <= 4; ++w) {
      EXPECT_EQ(undetected(c, pdu, w), 0u) << c.name << " weight " << w;
    }
  }
}

TEST(ProfisafeErrorDetection, HammingDistanceOfTheCandidate) {
  // Candidate variant, RS4 PDU: weight 5 all detected, weight 6 is the first with misses.
  for (const Case& c : cases()) {
    if (c.config.variant != Crc2Variant{}) continue;
    const std::uint64_t pdu = build_bits(c);
    const std::uint64_t w5 = undetected(c, pdu, 5);
    const std::uint64_t w6 = undetected(c, pdu, 6);
    std::printf("[ hd ] %s: undetected weight5 %llu of 658008, weight6 %llu of 3838380\n",
                c.name.c_str(), static_cast<unsigned long long>(w5),
                static_cast<unsigned long long>(w6));
    EXPECT_EQ(w5, 0u) << c.name;
    EXPECT_GT(w6, 0u) << c.name;  // so the code's Hamming distance here is exactly 6
  }
}

TEST(ProfisafeErrorDetection, ResidualRateOfRandomHeavyErrors) {
  // Uniform random non-zero 40-bit error patterns (mean weight 20), fixed seed.
  constexpr std::uint64_t kTrials = 4'000'000;
  for (const Case& c : cases()) {
    if (c.config.variant != Crc2Variant{}) continue;
    const std::uint64_t pdu = build_bits(c);
    std::mt19937_64 rng(0x5AFE);
    std::uint64_t missed = 0;
    for (std::uint64_t i = 0; i < kTrials; ++i) {
      std::uint64_t e = rng() & ((1ull << kBits) - 1);
      if (e == 0) e = 1;
      if (accepted(c, pdu ^ e)) ++missed;
    }
    const double rate = static_cast<double>(missed) / static_cast<double>(kTrials);
    std::printf("[ residual ] %s: %llu of %llu accepted = %.3g (2^-16 = %.3g)\n", c.name.c_str(),
                static_cast<unsigned long long>(missed), static_cast<unsigned long long>(kTrials),
                rate, 1.0 / 65536.0);
    // Bounded by 2^-16 (CRC alone); the number comparison adds up to a factor 2^-8.
    EXPECT_LT(rate, 2.0 / 65536.0) << c.name;
  }
}

}  // namespace
}  // namespace rs4sim::profisafe
