// Field pairs, faults, contamination, events, configuration (docs/rs4-scanner.md).
#include "scanner_test_support.h"

#include <gtest/gtest.h>

namespace rs4sim::rs4::scanner {
namespace {

using namespace testing;

ParameterSet restricted() {
  ParameterSet p = params(RestartMode::kAutomatic);
  p.permitted = {0x03, 0x03, 0x0C, 0x0C};  // 1↔2 and 3↔4 only
  return p;
}

TEST(ScannerFieldPairs, PermittedSwitchUsesTheNewFieldAndOverlapsOneScan) {
  ManualTime t;
  Scanner s = booted(restricted(), t);
  // An object at 1200 mm violates pair 2 (1500 mm) but not pair 1 (1000 mm).
  ASSERT_TRUE(s.edit_scene(t.now).add(intruder(1200)));
  s.advance(t.advance(milliseconds(200)));
  EXPECT_TRUE(s.ossd());
  EXPECT_FALSE(s.status().protective_violated);
  EXPECT_TRUE(s.status().warning_violated);  // pair 1 warning = 2000 mm
  s.select_field_pair(2, t.advance(milliseconds(1)));
  EXPECT_EQ(s.status().first_pair, 2);
  EXPECT_EQ(s.status().second_pair, 1);    // switch-over: two selected
  s.advance(t.advance(milliseconds(39)));  // the overlapping scan
  EXPECT_TRUE(s.status().protective_violated);
  EXPECT_FALSE(s.status().second_protective_violated);  // pair 1 is free
  EXPECT_EQ(s.status().second_pair, 1);
  s.advance(t.advance(milliseconds(40)));  // k = 2 scans on pair 2
  EXPECT_EQ(s.status().second_pair, 0);
  EXPECT_FALSE(s.ossd());
  EXPECT_EQ(s.counters().field_pair_switches, 1U);
  EXPECT_EQ(s.status().state, ScannerState::kMeasuring);
}

// The pair being left is still monitored in the overlapping scan (option 2 bit 5).
TEST(ScannerFieldPairs, PairBeingLeftIsMonitoredInTheOverlap) {
  ManualTime t;
  Scanner s = booted(restricted(), t);
  s.select_field_pair(2, t.now);
  ASSERT_TRUE(s.edit_scene(t.now).add(intruder(1200)));  // inside pair 2 (1500 mm) only
  s.advance(t.advance(milliseconds(120)));
  ASSERT_FALSE(s.ossd());
  s.select_field_pair(1, t.advance(milliseconds(1)));
  s.advance(t.advance(milliseconds(39)));              // overlapping scan
  EXPECT_FALSE(s.status().protective_violated);        // pair 1 free
  EXPECT_TRUE(s.status().second_protective_violated);  // pair 2 still occupied
  EXPECT_EQ(s.last_scan().second_pair, 2);
  EXPECT_TRUE(s.last_scan().second.protective.test(264));
  EXPECT_FALSE(s.ossd());                  // the overlap counts as violated
  s.advance(t.advance(milliseconds(40)));  // pair 1 alone: free
  EXPECT_FALSE(s.status().second_protective_violated);
  EXPECT_TRUE(s.ossd());  // automatic restart
}

TEST(ScannerFieldPairs, ForbiddenTransitionIsAFaultAcknowledgedByPulse) {
  ManualTime t;
  Scanner s = booted(restricted(), t);
  ASSERT_TRUE(s.ossd());
  s.select_field_pair(3, t.advance(milliseconds(5)));
  EXPECT_FALSE(s.ossd());
  EXPECT_EQ(s.status().state, ScannerState::kError);
  EXPECT_TRUE(s.faults()[static_cast<std::size_t>(Fault::kFieldPairSequence)].latched);
  const auto e = s.pop_event();
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->kind, Rs4Event::Kind::kError);
  EXPECT_EQ(e->number, 0x0401);
  EXPECT_EQ(e->parameter, 0x0103);  // from pair 1 to pair 3
  EXPECT_EQ(e->function, 0x0004);
  // Acknowledge with pair 3 still requested: a start goes via the start pair 1 → 3 again.
  pulse(s, t);
  EXPECT_EQ(s.status().state, ScannerState::kError);
  EXPECT_EQ(s.counters().faults, 2U);
  s.select_field_pair(2, t.now);  // 1 → 2 is permitted
  pulse(s, t);
  EXPECT_EQ(s.status().state, ScannerState::kMeasuring);
  EXPECT_EQ(s.status().first_pair, 2);
  s.advance(t.advance(milliseconds(40)));
  EXPECT_TRUE(s.ossd());
}

TEST(ScannerFieldPairs, InvalidNumberIsAFault) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic), t);
  s.select_field_pair(0, t.now);
  EXPECT_FALSE(s.ossd());
  EXPECT_TRUE(s.faults()[static_cast<std::size_t>(Fault::kFieldPairInvalid)].latched);
  EXPECT_EQ(s.pop_event()->number, 0x0402);
}

// [RS4 manual §5.1.2] Info: the start uses the start pair; the requested pair must be reachable
// from it.
TEST(ScannerFieldPairs, StartGoesThroughTheStartPair) {
  ManualTime t;
  Scanner s;
  ASSERT_TRUE(s.set_parameters(restricted(), t.now));
  s.select_field_pair(4, t.now);  // not permitted from 1
  s.power_on(t.now);
  s.advance(t.advance(seconds(30)));
  EXPECT_EQ(s.status().state, ScannerState::kError);
  EXPECT_FALSE(s.ossd());
}

TEST(ScannerFaults, InjectedFaultNeedsClearAndAcknowledge) {
  ManualTime t;
  Scanner s = started(RestartMode::kStartInterlock, t);
  ASSERT_TRUE(s.ossd());
  ASSERT_TRUE(s.inject_fault(Fault::kMotorSpeed, t.now));
  EXPECT_FALSE(s.ossd());
  EXPECT_EQ(s.status().state, ScannerState::kError);
  EXPECT_TRUE(s.status().fault);
  EXPECT_EQ(s.pop_event()->number, 0x0201);
  pulse(s, t);  // cause still present
  EXPECT_EQ(s.status().state, ScannerState::kError);
  ASSERT_TRUE(s.clear_fault(Fault::kMotorSpeed, t.now));
  EXPECT_EQ(s.status().state, ScannerState::kError);  // latched until acknowledged
  pulse(s, t);                                        // acknowledge → new start
  EXPECT_EQ(s.status().state, ScannerState::kMeasuring);
  EXPECT_FALSE(s.ossd());  // start interlock
  pulse(s, t);
  EXPECT_TRUE(s.ossd());
  EXPECT_EQ(s.faults()[static_cast<std::size_t>(Fault::kMotorSpeed)].occurrences, 1U);
}

TEST(ScannerFaults, FaultDuringBootShowsAtBootEnd) {
  ManualTime t;
  Scanner s;
  s.power_on(t.now);
  ASSERT_TRUE(s.inject_fault(Fault::kInternalHardware, t.advance(seconds(10))));
  EXPECT_EQ(s.status().state, ScannerState::kInitialisation);
  EXPECT_EQ(s.pop_event()->number, 0x0102);
  s.advance(t.advance(seconds(20)));
  EXPECT_EQ(s.status().state, ScannerState::kError);
  EXPECT_FALSE(s.ossd());
}

// The error numbers are the project's (EXTENSION); this pins the documented table.
TEST(ScannerFaults, ErrorNumbersAsDocumented) {
  struct Row {
    Fault fault;
    std::uint16_t number;
    std::uint16_t function;
  };
  const Row rows[] = {
      {Fault::kOssdCrossCircuit, 0x0101, 1},   {Fault::kInternalHardware, 0x0102, 1},
      {Fault::kMotorSpeed, 0x0201, 2},         {Fault::kDazzled, 0x0202, 2},
      {Fault::kWindowContaminated, 0x0302, 3}, {Fault::kFieldPairSequence, 0x0401, 4},
      {Fault::kFieldPairInvalid, 0x0402, 4}};
  for (const Row& r : rows) {
    EXPECT_EQ(fault_info(r.fault).error_number, r.number);
    EXPECT_EQ(fault_info(r.fault).function, r.function);
  }
}

// Every injectable fault switches the OSSDs off at once and raises its own event.
TEST(ScannerFaults, EachInjectedFaultSwitchesOffImmediately) {
  for (const Fault f :
       {Fault::kOssdCrossCircuit, Fault::kInternalHardware, Fault::kMotorSpeed, Fault::kDazzled}) {
    ManualTime t;
    Scanner s = booted(params(RestartMode::kAutomatic), t);
    ASSERT_TRUE(s.ossd());
    ASSERT_TRUE(s.inject_fault(f, t.advance(milliseconds(3))));
    EXPECT_FALSE(s.ossd());
    EXPECT_EQ(s.pop_event()->number, fault_info(f).error_number);
    EXPECT_EQ(s.faults()[static_cast<std::size_t>(f)].occurrences, 1U);
    ASSERT_TRUE(s.inject_fault(f, t.now));  // persisting: no new event
    EXPECT_EQ(s.pending_events(), 0U);
  }
}

TEST(ScannerFaults, ContaminationWarningThenFault) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic), t);
  s.set_contamination(49, t.now);
  EXPECT_FALSE(s.status().warning_output);
  EXPECT_EQ(s.pending_events(), 0U);
  s.set_contamination(50, t.now);
  EXPECT_TRUE(s.status().warning_output);  // factory: contamination
  EXPECT_TRUE(s.status().contamination_warning);
  EXPECT_TRUE(s.ossd());
  const auto w = s.pop_event();
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->kind, Rs4Event::Kind::kWarning);
  EXPECT_EQ(w->number, 0x0301);
  EXPECT_EQ(w->parameter, 50);
  s.set_contamination(60, t.now);
  EXPECT_EQ(s.pending_events(), 0U);  // one event per rising edge
  s.set_contamination(80, t.now);
  EXPECT_FALSE(s.ossd());
  EXPECT_EQ(s.pop_event()->number, 0x0302);
  s.set_contamination(10, t.now);
  EXPECT_FALSE(s.status().warning_output);
  pulse(s, t);
  s.advance(t.advance(milliseconds(40)));
  EXPECT_TRUE(s.ossd());
}

TEST(ScannerFaults, WarningOutputFollowsWarningFieldWhenAssigned) {
  ManualTime t;
  ParameterSet p = params(RestartMode::kAutomatic);
  p.warning_output = kWarnOnWarningField;
  Scanner s = booted(p, t);
  ASSERT_TRUE(s.edit_scene(t.now).add(intruder(1500)));  // warning field only
  s.advance(t.advance(milliseconds(40)));
  EXPECT_TRUE(s.status().warning_output);
  EXPECT_TRUE(s.ossd());
  s.set_contamination(60, t.now);  // not assigned
  s.edit_scene(t.now).clear();
  s.advance(t.advance(milliseconds(40)));
  EXPECT_FALSE(s.status().warning_output);
}

TEST(ScannerFaults, WarningOutputOnFaultAndInterlockWhenAssigned) {
  ManualTime t;
  ParameterSet p = params(RestartMode::kStartInterlock);
  p.warning_output = kWarnOnFault | kWarnOnRestartInterlock;
  Scanner s = booted(p, t);
  EXPECT_TRUE(s.status().warning_output);  // interlock waits
  pulse(s, t);
  EXPECT_FALSE(s.status().warning_output);
  ASSERT_TRUE(s.inject_fault(Fault::kDazzled, t.now));
  EXPECT_TRUE(s.status().warning_output);  // error state
  s.set_contamination(90, t.now);          // contamination not assigned
  ASSERT_TRUE(s.clear_fault(Fault::kDazzled, t.now));
  EXPECT_TRUE(s.status().warning_output);
}

TEST(ScannerFaults, UnknownFaultValueIsATypedError) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic), t);
  EXPECT_EQ(s.inject_fault(static_cast<Fault>(kFaultCount), t.now).error(),
            ScannerError::kUnknownFault);
  EXPECT_EQ(s.clear_fault(static_cast<Fault>(255), t.now).error(), ScannerError::kUnknownFault);
  EXPECT_TRUE(s.ossd());
  EXPECT_EQ(fault_info(static_cast<Fault>(200)).error_number, 0);
  EXPECT_EQ(fault_info(static_cast<Fault>(200)).name, "unknown");
}

TEST(ScannerFaults, EventQueueKeepsNewestSixteen) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic), t);
  for (int i = 0; i < 20; ++i) {
    s.set_contamination(60, t.now);
    s.set_contamination(0, t.now);
  }
  EXPECT_EQ(s.pending_events(), Scanner::kEventCapacity);
  EXPECT_EQ(s.counters().events_dropped, 4U);
}

TEST(ScannerConfiguration, ParametersChangeOnlyInConfiguration) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic), t);
  ParameterSet p = params(RestartMode::kAutomatic, 2);
  p.identity.serial_number = 4242;
  EXPECT_EQ(s.set_parameters(p, t.now).error(), ScannerError::kNotInConfiguration);
  ASSERT_TRUE(s.enter_configuration(t.now));
  EXPECT_EQ(s.status().state, ScannerState::kConfiguration);
  EXPECT_FALSE(s.ossd());
  ParameterSet bad = p;
  bad.start_pair = 7;
  EXPECT_EQ(s.set_parameters(bad, t.now).error(), ScannerError::kInvalidParameterSet);
  ASSERT_TRUE(s.set_parameters(p, t.now));
  EXPECT_EQ(s.parameters().response_steps, 2);
  EXPECT_EQ(s.parameters().identity.serial_number, ScannerConfig{}.identity.serial_number);
  ASSERT_TRUE(s.leave_configuration(t.now));
  EXPECT_EQ(s.status().state, ScannerState::kMeasuring);
  EXPECT_TRUE(s.ossd());
  EXPECT_EQ(s.leave_configuration(t.now).error(), ScannerError::kNotInConfiguration);
}

TEST(ScannerConfiguration, FactoryResetKeepsIdentityAndPasswords) {
  ManualTime t;
  ParameterSet p = params(RestartMode::kAutomatic, 5);
  p.passwords[0] = {'S', 'E', 'C', 'R', 'E', 'T', 0xFF, 0xFF};
  Scanner s = booted(p, t);
  EXPECT_FALSE(s.factory_settings());
  const std::uint32_t before = s.parameter_checksum();
  s.reset_to_factory_default(t.now);
  EXPECT_TRUE(s.factory_settings());
  EXPECT_NE(s.parameter_checksum(), before);
  EXPECT_EQ(s.parameters().response_steps, 0);
  EXPECT_EQ(s.parameters().passwords[0], p.passwords[0]);
  EXPECT_EQ(s.parameters().identity, ScannerConfig{}.identity);
  EXPECT_EQ(s.status().state, ScannerState::kMeasuring);
  EXPECT_FALSE(s.ossd());  // factory: start interlock
  EXPECT_STREQ(to_string(s.status().state), "measuring");
}

TEST(ScannerLifecycle, PowerCycleRebootsAndResetsCounter) {
  ManualTime t;
  Scanner s = booted(params(RestartMode::kAutomatic), t);
  s.advance(t.advance(seconds(1)));
  EXPECT_GT(s.status().scan_counter, 1U);
  s.power_cycle(t.now);
  EXPECT_EQ(s.status().state, ScannerState::kInitialisation);
  EXPECT_FALSE(s.ossd());
  EXPECT_EQ(s.status().scan_counter, 0U);
  s.advance(t.advance(seconds(30)));
  EXPECT_TRUE(s.ossd());
  EXPECT_EQ(s.counters().boots, 2U);
  s.power_off(t.now);
  EXPECT_EQ(s.status().state, ScannerState::kOff);
  EXPECT_EQ(s.next_deadline(), TimePoint::max());
}

}  // namespace
}  // namespace rs4sim::rs4::scanner
