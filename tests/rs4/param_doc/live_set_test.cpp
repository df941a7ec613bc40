// The parameter set over the RS4's RS232 port (rs232_set_client.h) against the live port
// (rs4/rs232, in-process on the manual clock, tests/rs4/rs232/rs232_fixture.h): read the
// device's set, write a document's set with the password, a wrong password changes nothing.
#include "rs4/param_doc/parameter_document.h"
#include "rs4/param_doc/rs232_set_client.h"
#include "rs4/scanner/parameter_codec.h"
#include "tests/rs4/rs232/rs232_fixture.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::param_doc {
namespace {

using rs232::testing::PortFixture;

struct Live : PortFixture {
  Live() {
    boot();
    port.attach(clock.now());
    exchange = [this](std::span<const std::uint8_t> frame) -> std::optional<rs232::Answer> {
      auto frames = feed({frame.begin(), frame.end()});
      const auto later = run_for(std::chrono::milliseconds(500));
      frames.insert(frames.end(), later.begin(), later.end());
      for (const auto& f : frames) {  // the 0x23 stream interleaves: skip it
        const auto a = decode(f);
        if (!std::holds_alternative<protocol::MeasurementTelegram>(a)) return a;
      }
      return std::nullopt;
    };
  }
  Exchange exchange;
};

TEST(LiveSet, ReadsTheDevicesSetWithItsIdentityAndWithoutPasswords) {
  Live f;
  const auto live = read_live_set(f.exchange);
  ASSERT_TRUE(live.set) << live.error;
  scanner::ParameterSet expected = f.adapter.scanner().parameters();
  for (auto& pw : expected.passwords) pw.fill(0xFF);
  EXPECT_EQ(*live.set, expected);
}

TEST(LiveSet, WritesADocumentsSetWithThePassword) {
  Live f;
  const auto live = read_live_set(f.exchange);
  ASSERT_TRUE(live.set) << live.error;
  const auto doc =
      from_document(R"({"format": 1, "response_time_ms": 160, "start_pair": 2})", *live.set);
  ASSERT_TRUE(doc) << doc.issue.message();
  const auto password = *rs232::make_password("ROD4LE");  // factory state: service password
  EXPECT_EQ(write_live_set(f.exchange, *doc.set, password), "");
  const auto& now = f.adapter.scanner().parameters();
  EXPECT_EQ(now.response_steps, 2);
  EXPECT_EQ(now.start_pair, 2);
  EXPECT_EQ(scanner::encode_for_transfer(now), scanner::encode_for_transfer(*doc.set));
}

TEST(LiveSet, WrongPasswordIsRefusedAndChangesNothing) {
  Live f;
  const auto before = f.adapter.scanner().parameters();
  scanner::ParameterSet changed = before;
  changed.response_steps = 5;
  const auto error = write_live_set(f.exchange, changed, *rs232::make_password("guess"));
  EXPECT_NE(error.find("wrong password"), std::string::npos) << error;
  EXPECT_EQ(f.adapter.scanner().parameters(), before);
}

TEST(LiveSet, DetachedPortIsSilent) {
  Live f;
  f.port.detach(f.clock.now());
  const auto live = read_live_set(f.exchange);
  EXPECT_FALSE(live.set);
  EXPECT_NE(live.error.find("no answer"), std::string::npos) << live.error;
}

}  // namespace
}  // namespace rs4sim::rs4::param_doc
