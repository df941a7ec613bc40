// The transfer form of a parameter set ([docs/proxy-protocol.md]): encode() with identity and
// user passwords zeroed, its CRC-32, the scanner's change counter and the factory reset that
// keeps passwords and identity ([RS4 manual §7.1, §7.2, §7.2.4]).
#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"
#include "scanner_test_support.h"

namespace rs4sim::rs4::scanner::testing {
namespace {

ParameterSet with_secrets() {
  ParameterSet s = factory_default();
  s.identity = Identity{0x00ABCDEF, 0x0004, 2, 7};
  s.passwords[0] = {'S', 'E', 'C', 'R', 'E', 'T', 0xFF, 0xFF};
  s.passwords[1] = {'a', 'b', 'c', 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
  s.response_steps = 3;
  return s;
}

TEST(TransferForm, IdentityAndPasswordsAreZeroed) {
  const auto blob = encode_for_transfer(with_secrets());
  ASSERT_EQ(blob.size(), kParameterSetSize);
  // Header layout (docs/rs4-scanner.md "Encoding"): 0..3 "RS4P", 4 version, 5 reserved,
  // 6..9 serial, 10..11 device type, 12 fw major, 13 fw minor, 14 response steps, ...,
  // 27..42 the two 8-byte passwords.
  EXPECT_EQ(blob[0], 'R');
  EXPECT_EQ(blob[4], 0x01);  // format version 1
  for (std::size_t i = 6; i <= 13; ++i) EXPECT_EQ(blob[i], 0x00) << "identity byte " << i;
  EXPECT_EQ(blob[14], 0x03);  // response steps kept
  for (std::size_t i = 27; i <= 42; ++i) EXPECT_EQ(blob[i], 0x00) << "password byte " << i;
  // Everything else is encode() unchanged.
  auto full = encode(with_secrets());
  for (std::size_t i = 6; i <= 13; ++i) full[i] = 0;
  for (std::size_t i = 27; i <= 42; ++i) full[i] = 0;
  EXPECT_EQ(blob, full);
}

TEST(TransferForm, ChecksumIgnoresIdentityAndPasswords) {
  const auto a = with_secrets();
  auto b = a;
  b.identity = Identity{1, 2, 3, 4};
  b.passwords[0].fill(0xFF);
  EXPECT_EQ(transfer_checksum(a), transfer_checksum(b));
  EXPECT_NE(checksum(a), checksum(b));
  EXPECT_EQ(transfer_checksum(a), crc32_iso_hdlc(encode_for_transfer(a)));
  b.response_steps = 4;  // a real parameter changes it
  EXPECT_NE(transfer_checksum(a), transfer_checksum(b));
}

TEST(TransferForm, DecodesButNeedsTheDevicePasswordsToValidate) {
  const auto decoded = decode(encode_for_transfer(with_secrets()));
  ASSERT_TRUE(decoded);
  EXPECT_TRUE(validate(decoded.value()).has_value());  // 00 is not a password byte
  const auto merged = merge_download(with_secrets(), decoded.value());
  EXPECT_FALSE(validate(merged).has_value());
  EXPECT_EQ(merged, with_secrets());
}

TEST(ChangeCounter, CountsEverySetWriteAndSurvivesPowerCycles) {
  ManualTime t;
  Scanner s = booted(factory_default(), t);
  EXPECT_EQ(s.change_counter(), 1);  // booted() wrote the set once
  ASSERT_TRUE(s.enter_configuration(t.now));
  ASSERT_TRUE(s.set_parameters(with_secrets(), t.now));
  ASSERT_TRUE(s.leave_configuration(t.now));
  EXPECT_EQ(s.change_counter(), 2);
  EXPECT_FALSE(s.set_parameters(with_secrets(), t.now));  // refused: not counted
  EXPECT_EQ(s.change_counter(), 2);
  s.reset_to_factory_default(t.now);
  EXPECT_EQ(s.change_counter(), 3);
  s.power_cycle(t.advance(seconds(1)));
  EXPECT_EQ(s.change_counter(), 3);
}

TEST(FactoryReset, KeepsPasswordsAndIdentity) {
  ManualTime t;
  ScannerConfig cfg;
  cfg.identity = Identity{0x00777777, 0x0004, 1, 3};
  Scanner s(cfg);
  ASSERT_TRUE(s.set_parameters(with_secrets(), t.now));
  s.power_on(t.now);
  s.advance(t.advance(seconds(30)));
  ASSERT_FALSE(s.factory_settings());
  s.reset_to_factory_default(t.now);
  EXPECT_TRUE(s.factory_settings());
  EXPECT_EQ(s.parameters().passwords, with_secrets().passwords);
  EXPECT_EQ(s.parameters().identity, cfg.identity);
  EXPECT_EQ(s.parameters().response_steps, 0);
  EXPECT_EQ(s.status().state, ScannerState::kMeasuring);
  EXPECT_EQ(s.transfer_checksum(), transfer_checksum(factory_default()));
}

TEST(FactoryReset, EndsAConfiguration) {
  ManualTime t;
  Scanner s = booted(with_secrets(), t);
  ASSERT_TRUE(s.enter_configuration(t.now));
  s.reset_to_factory_default(t.now);
  EXPECT_EQ(s.status().state, ScannerState::kMeasuring);
  EXPECT_TRUE(s.factory_settings());
}

}  // namespace
}  // namespace rs4sim::rs4::scanner::testing

namespace rs4sim::rs4::scanner {
namespace {

TEST(TransferForm, DecodeTransferFormValidatesAllButThePasswords) {
  auto set = factory_default();
  set.response_steps = 3;
  const auto decoded = decode_transfer_form(encode_for_transfer(set));
  ASSERT_TRUE(decoded) << decoded.error().message();
  EXPECT_EQ(decoded.value().response_steps, 3);
  EXPECT_EQ(decoded.value().passwords[0], Password{});  // as transferred: blank
  // decode_and_validate refuses the same bytes: zero bytes are no password.
  EXPECT_FALSE(decode_and_validate(encode_for_transfer(set)));
  auto bad = set;
  bad.response_steps = kMaxResponseSteps + 1;
  EXPECT_EQ(decode_transfer_form(encode_for_transfer(bad)).error(),
            make_error_code(validate(bad)->error));
}

}  // namespace
}  // namespace rs4sim::rs4::scanner
