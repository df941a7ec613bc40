// libFuzzer target: the Scanner state machine driven by a byte script (two bytes per
// step: operation, argument). Invariants after every step ([docs/rs4-scanner.md §4]):
// the OSSDs are on only in measuring state with no latched fault, no held restart and
// no waiting interlock; the next deadline always lies in the future while scanning.
#include "rs4/scanner/scanner.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace {

using namespace rs4sim::rs4::scanner;
using std::chrono::milliseconds;

void check(const Scanner& s, TimePoint now) {
  const ScannerStatus st = s.status();
  if (st.ossd) {
    if (st.state != ScannerState::kMeasuring || st.fault || st.restart_held ||
        st.restart_interlock) {
      std::abort();
    }
    for (const FaultState& f : s.faults()) {
      if (f.latched) std::abort();
    }
  }
  const bool scanning = st.state == ScannerState::kMeasuring || st.state == ScannerState::kError;
  if (scanning && s.next_deadline() <= now) std::abort();
}

void configure(Scanner& s, std::uint8_t arg, TimePoint now) {
  if (!s.enter_configuration(now)) return;
  ParameterSet p = factory_default();
  p.restart_mode = static_cast<RestartMode>(arg % 4);      // 3 is refused
  p.response_steps = static_cast<std::uint8_t>(arg >> 4);  // 15 is refused
  p.permitted = {static_cast<std::uint8_t>(0x01 | (arg & 0x0E)), 0x0F, 0x0C, 0x0F};
  (void)s.set_parameters(p, now);
  (void)s.leave_configuration(now);
}

void step(Scanner& s, TimePoint& now, std::uint8_t op, std::uint8_t arg) {
  switch (op % 10) {
    case 0:
      now += milliseconds(arg);
      s.advance(now);
      break;  // 0..255 ms
    case 1: s.set_restart_input((arg & 1) != 0, now); break;
    case 2: s.select_field_pair(arg & 7, now); break;
    case 3: s.set_contamination(static_cast<std::uint8_t>(arg % 101), now); break;
    case 4: (void)s.inject_fault(static_cast<Fault>(arg % (kFaultCount + 1)), now); break;
    case 5: (void)s.clear_fault(static_cast<Fault>(arg % (kFaultCount + 1)), now); break;
    case 6:  // at most 8 obstacles
      if (s.scene().obstacles().size() >= 8) break;
      (void)s.edit_scene(now).add(Circle{{static_cast<double>(static_cast<std::int8_t>(arg)) * 40.0,
                                          static_cast<double>(arg) * 15.0},
                                         static_cast<double>(arg % 64) + 1.0});
      break;
    case 7: (void)s.edit_scene(now).remove(arg % 16); break;
    case 8:
      if ((arg & 1) != 0)
        s.power_cycle(now);
      else
        s.power_off(now);
      if ((arg & 2) != 0) s.power_on(now);
      break;
    default: configure(s, arg, now); break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ScannerConfig cfg;
  cfg.boot_duration = milliseconds(100);  // reach measuring within a short script
  Scanner s(cfg);
  TimePoint now{std::chrono::hours(1)};
  s.power_on(now);
  for (std::size_t i = 0; i + 1 < size && i < 512; i += 2) {  // ≤ 256 steps
    step(s, now, data[i], data[i + 1]);
    check(s, now);
  }
  return 0;
}
