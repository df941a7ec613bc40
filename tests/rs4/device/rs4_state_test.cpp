// The RS4's state file (rs4/device/rs4_state.h): the header byte by byte, the set behind it,
// each refusal, and a unit made from it that is the same unit with the same set.
#include "rs4/device/rs4_state.h"

#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::device {
namespace {

using Bytes = std::vector<std::uint8_t>;

Rs4State site_state() {
  Rs4State s;
  s.set = scanner::factory_default();
  s.set.identity = {0x00054321, 0x0004, 1, 0};
  s.set.response_steps = 2;  // 160 ms [RS4 manual §6.6]
  s.set.passwords[0] = {'L', 'E', 'U', 'Z', 'E', 0xFF, 0xFF, 0xFF};
  s.switches = {0x1, 0x2};  // station 18
  return s;
}

// The CRC-32 of the file's last four bytes, written again over `bytes` (for a refusal that
// must be found behind a sound CRC).
void reseal(Bytes& bytes) {
  const auto crc = scanner::crc32_iso_hdlc(std::span(bytes).first(bytes.size() - 4));
  for (std::size_t i = 0; i < 4; ++i) {
    bytes[bytes.size() - 4 + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
  }
}

TEST(Rs4State, HeaderBytes) {
  const auto state = site_state();
  const Bytes file = encode_state(state);
  const Bytes set = scanner::encode(state.set);
  ASSERT_EQ(set.size(), 8507U);  // the set's encoding (docs/rs4-scanner.md "Encoding")
  ASSERT_EQ(file.size(), 16U + 8507U + 4U);
  const Bytes header(file.begin(), file.begin() + 16);
  EXPECT_EQ(header, (Bytes{'R', 'S', '4', 'S', 'I', 'M', 'N', 'V',  // magic
                           0x01,                                    // format version 1
                           0x01,                                    // kind: RS4/PROFIsafe
                           0x01, 0x02,                              // HexH 1, HexL 2
                           0x00, 0x00, 0x21, 0x3B}));               // N = 8507
  EXPECT_TRUE(std::equal(set.begin(), set.end(), file.begin() + 16));
  // CRC-32/ISO-HDLC (check value of "123456789": CBF43926) over bytes 0 .. 15+N, high byte first.
  const std::uint8_t nine[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  ASSERT_EQ(scanner::crc32_iso_hdlc(nine), 0xCBF43926U);
  const auto crc = scanner::crc32_iso_hdlc(std::span(file).first(16 + 8507));
  EXPECT_EQ(file[16 + 8507], static_cast<std::uint8_t>(crc >> 24));
  EXPECT_EQ(file[16 + 8507 + 3], static_cast<std::uint8_t>(crc));
}

TEST(Rs4State, DecodesWhatWasKeptWithPasswordsAndSerialNumber) {
  const auto state = site_state();
  const auto back = decode_state(encode_state(state));
  ASSERT_TRUE(back) << back.error().message();
  EXPECT_EQ(back.value(), state);
  EXPECT_EQ(back.value().set.identity.serial_number, 0x00054321U);
  EXPECT_EQ(back.value().set.passwords[0], state.set.passwords[0]);
}

TEST(Rs4State, RefusesWhatIsNotThisDevicesMemory) {
  const Bytes good = encode_state(site_state());
  const auto error = [](Bytes b) {
    const auto r = decode_state(b);
    return r ? std::error_code{} : r.error();
  };
  EXPECT_EQ(error({}), StateError::kNotAStateFile);
  EXPECT_EQ(error(Bytes{'{', '"', 'f', 'o', 'r', 'm', 'a', 't', '"'}), StateError::kNotAStateFile);
  auto b = good;
  b[8] = 0x02;  // format version 2: a newer rs4sim's
  EXPECT_EQ(error(b), StateError::kNewerFormat);
  b = good;
  b[9] = 0x02;  // another device kind
  EXPECT_EQ(error(b), StateError::kOtherDevice);
  b = good;
  b.resize(b.size() - 1);  // cut
  EXPECT_EQ(error(b), StateError::kTruncated);
  b = good;
  b.push_back(0);  // a byte after the CRC
  EXPECT_EQ(error(b), StateError::kTruncated);
  b = good;
  b[16 + 100] ^= 0x01;  // one bit of the set
  EXPECT_EQ(error(b), StateError::kCorrupt);
  b = good;
  b[10] = 0x10;  // HexH 16
  reseal(b);
  EXPECT_EQ(error(b), StateError::kBadSwitches);
  b = good;
  b[16 + 4] ^= 0xFF;  // the set's own header, behind a sound CRC
  reseal(b);
  EXPECT_EQ(error(b), StateError::kBadSet);
  EXPECT_EQ(make_error_code(StateError::kCorrupt).message(), "corrupt (CRC-32 mismatch)");
}

TEST(Rs4State, AUnitMadeFromItIsTheSameUnitWithTheSameSet) {
  const auto state = site_state();
  Rs4Device device(with_state({}, state));
  ASSERT_TRUE(restore_state(device, state, dp::TimePoint{}));
  EXPECT_EQ(capture_state(device), state);
  EXPECT_EQ(device.scanner().parameters().identity.serial_number, 0x00054321U);
  device.power_on(dp::TimePoint{});
  EXPECT_EQ(device.address(), 18);  // the switches 1/2 [RS4 manual §4.5]
  // Powered: a set goes in through configuration only, not by restore.
  EXPECT_FALSE(restore_state(device, state, dp::TimePoint{}));
}

TEST(Rs4State, TheMarkMovesWithEverySetWriteSerialNumberAndSwitch) {
  Rs4Device device;
  const auto before = state_mark(device);
  device.set_address_switches({0x0, 0x5});
  EXPECT_NE(state_mark(device), before);
  const auto switched = state_mark(device);
  ASSERT_TRUE(device.scanner().set_parameters(scanner::factory_default(), dp::TimePoint{}));
  EXPECT_NE(state_mark(device), switched);
  const auto written = state_mark(device);
  ASSERT_TRUE(device.exchange_unit(777, dp::TimePoint{}));
  EXPECT_NE(state_mark(device), written);
  EXPECT_EQ(state_mark(device).serial_number, 777U);
}

}  // namespace
}  // namespace rs4sim::rs4::device
