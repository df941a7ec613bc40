// The error answers E1..E5 of the manual's "ERROR HANDLING" paragraphs, as annotated bytes,
// and their order parity -> address -> E1 -> E2 -> E3/E5 -> E4 [METRON manual "No node"].
// Error reply codes 0xE1..0xE5 are the project's EXTENSION (metron/wire_table.h).
#include "tests/metron/metron_line.h"

#include <gtest/gtest.h>

namespace rs4sim::metron::testing {
namespace {

using namespace std::chrono_literals;

const Bytes kE1{0x02, 0x01, 0xE1, 0x1E};
const Bytes kE2{0x02, 0x01, 0xE2, 0x1D};
const Bytes kE3{0x02, 0x01, 0xE3, 0x1C};
const Bytes kE4{0x02, 0x01, 0xE4, 0x1B};
const Bytes kE5{0x02, 0x01, 0xE5, 0x1A};

TEST(MetronSlaveErrors, E1WrongChecksum) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0C, 0xF4 /* should be F3 */}), kE1);
  EXPECT_EQ(rig.device().counters().errors[0], 1U);
}

TEST(MetronSlaveErrors, E1WrongChecksumOnResetIsAnsweredAndNotExecuted) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x01, 0x00}), kE1);
  EXPECT_EQ(rig.device().counters().resets, 0U);
}

TEST(MetronSlaveErrors, E1LengthAboveSix) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02, 0x07 /* > 6 */, 0x0A, 1, 2, 3, 4, 5, 6, 0x00}), kE1);
  const auto c = rig.device().counters();
  EXPECT_EQ(c.too_long, 1U);
  EXPECT_EQ(c.resync_bytes, 8U);  // the rest of the message is not read as a new one
}

TEST(MetronSlaveErrors, E2WrongLength) {
  Rig rig(slave_options());
  // #12 with a data byte: length 2 where 1 is right; checksum correct.
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x0C, 0x00, 0xF3}), kE2);
  // #7 without its measurement field (length 1 where 2 is right).
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x07, 0xF8}), kE2);
  // #8 with a data byte.
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x08, 0x01, 0xF6}), kE2);
  // #1 with a data byte: not executed.
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x01, 0x00, 0xFE}), kE2);
  EXPECT_EQ(rig.device().counters().resets, 0U);
}

TEST(MetronSlaveErrors, E2BadArguments) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x07, 0x09 /* no such field */, 0xEF}), kE2);
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x09, 0x19 /* beam 25 of 24 */, 0xDD}), kE2);
  EXPECT_EQ(only_reply(rig, {0x02, 0x03, 0x0A, 0x01, 0x09 /* no such field */, 0xEB}), kE2);
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x0A, 0xF5 /* no field at all */}), kE2);
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x77 /* no such command */, 0x88}), kE2);
  EXPECT_EQ(only_reply(rig, {0x02, 0x00 /* no command */, 0xFF}), kE2);
}

TEST(MetronSlaveErrors, E2OssdCommandsNeedInputTypeNoFunction) {
  auto o = slave_options();
  o.input_type = InputType::kEnableAll;
  Rig rig(o);
  for (std::uint8_t c = 0x02; c <= 0x06; ++c)
    EXPECT_EQ(only_reply(rig, {0x02, 0x01, c, static_cast<std::uint8_t>(~c)}), kE2) << int{c};
  EXPECT_EQ(rig.device().slave_state().ossd, OssdFunction::kEnabled);
}

TEST(MetronSlaveErrors, E3OssdNotEnabled) {
  Rig rig(slave_options());
  rig.exchange({0x02, 0x01, 0x03, 0xFC});                    // disable
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x03, 0xFC}), kE3);  // disable again
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x04, 0xFB}), kE3);  // stand-by
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x05, 0xFA}), kE3);  // start OSSD measurement
}

TEST(MetronSlaveErrors, E3StopOssdWithoutStart) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x06, 0xF9}), kE3);
}

TEST(MetronSlaveErrors, E4SynchronismMissing) {
  Rig rig(slave_options());
  rig.device().set_synchronised(false);
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x07, 0x01, 0xF7}), kE4);  // #7
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x0A, 0x01, 0xF4}), kE4);  // #10
  rig.device().set_synchronised(true);
  rig.exchange({0x02, 0x02, 0x07, 0x01, 0xF7});
  rig.device().set_synchronised(false);
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x08, 0xF7}), kE4);       // #8
  EXPECT_TRUE(rig.device().slave_state().measuring.has_value());  // goes on
}

TEST(MetronSlaveErrors, E5StopMeasurementWithoutStart) {
  Rig rig(slave_options());
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x08, 0xF7}), kE5);
}

TEST(MetronSlaveErrors, OrderE1BeforeE2BeforeE5BeforeE4) {
  Rig rig(slave_options());
  rig.device().set_synchronised(false);
  // wrong length AND wrong checksum -> E1
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x08, 0x01, 0x00}), kE1);
  // wrong length, no Start, no synchronism -> E2
  EXPECT_EQ(only_reply(rig, {0x02, 0x02, 0x08, 0x01, 0xF6}), kE2);
  // no Start and no synchronism -> E5 first (the project's order)
  EXPECT_EQ(only_reply(rig, {0x02, 0x01, 0x08, 0xF7}), kE5);
}

TEST(MetronSlaveErrors, CommandsAreNotExecutedOnError) {
  Rig rig(slave_options());
  rig.exchange({0x02, 0x01, 0x03, 0x00});  // disable with a bad checksum: E1
  EXPECT_EQ(rig.device().slave_state().ossd, OssdFunction::kEnabled);
  EXPECT_EQ(rig.device().counters().executed, 0U);
}

}  // namespace
}  // namespace rs4sim::metron::testing
