// Config::validate(): every field range gets its own typed error.
#include "dp/slave/slave.h"
#include "dp/slave/slave_error.h"
#include "tests/dp/slave/fake_application.h"

#include <gtest/gtest.h>

namespace rs4sim::dp {
using namespace ::rs4sim::dp::slave;  // the slave under test
namespace {

std::error_code check(void (*mutate)(Config&)) {
  Config c;
  mutate(c);
  return c.validate();
}

TEST(Config, DefaultsAreValid) { EXPECT_FALSE(Config{}.validate()); }

TEST(Config, EachRangeHasItsError) {
  EXPECT_EQ(check([](Config& c) { c.address = 127; }),
            make_error_code(SlaveError::kInvalidAddress));
  EXPECT_EQ(check([](Config& c) { c.max_diag_length = 5; }),
            make_error_code(SlaveError::kInvalidMaxDiagLength));
  EXPECT_EQ(check([](Config& c) { c.max_diag_length = 245; }),
            make_error_code(SlaveError::kInvalidMaxDiagLength));
  EXPECT_EQ(check([](Config& c) { c.min_tsdr_default = 10; }),
            make_error_code(SlaveError::kInvalidMinTsdr));
  EXPECT_EQ(check([](Config& c) { c.alarm_capacity = 0; }),
            make_error_code(SlaveError::kInvalidAlarmCapacity));
  EXPECT_EQ(check([](Config& c) {
              c.alarm_capacity = 9;
              c.alarm_sequence_numbers = 8;
            }),
            make_error_code(SlaveError::kInvalidAlarmCapacity));
  EXPECT_EQ(check([](Config& c) { c.alarm_sequence_numbers = 33; }),
            make_error_code(SlaveError::kInvalidAlarmCapacity));
  EXPECT_EQ(check([](Config& c) { c.alarm_queue_capacity = 0; }),
            make_error_code(SlaveError::kInvalidAlarmQueue));
  EXPECT_EQ(check([](Config& c) { c.c2_rm_send_timeout = 0; }),
            make_error_code(SlaveError::kInvalidC2Timeout));
  EXPECT_EQ(check([](Config& c) { c.c1_max_data_length = 241; }),
            make_error_code(SlaveError::kInvalidAcyclicLength));
  EXPECT_EQ(check([](Config& c) { c.c2_max_data_length = 0; }),
            make_error_code(SlaveError::kInvalidAcyclicLength));
  EXPECT_EQ(check([](Config& c) { c.c2_sap = 49; }), make_error_code(SlaveError::kInvalidC2Sap));
}

TEST(Config, SlaveRefusesAnInvalidConfig) {
  testing::FakeApplication app;
  Config c;
  c.address = 200;
  EXPECT_THROW(Slave(c, app), std::system_error);
  EXPECT_EQ(app.control, nullptr);
}

TEST(Config, ErrorMessagesAreSpecific) {
  EXPECT_EQ(make_error_code(SlaveError::kAlarmQueueFull).message(), "alarm queue full");
  EXPECT_STREQ(make_error_code(SlaveError::kAlarmQueueFull).category().name(), "dp.slave");
  EXPECT_STREQ(to_string(State::kWaitCfg), "Wait_Cfg");
  EXPECT_STREQ(to_string(TransitionReason::kWatchdog), "watchdog expired");
}

}  // namespace
}  // namespace rs4sim::dp
