#pragma once
// The RS4 scanner model ([RS4 manual §2.3, §2.4, §5.1, §5.2.3, §4.3, §7.1]).
// A pure core: inputs and `now` in, state and the next deadline out; no clock reads,
// no I/O. Behaviour and the modelling decisions are documented in docs/rs4-scanner.md.
//
// Safety rule ([docs/design.md#one-predicate-for-the-safe-state]): one value per fault
// (FaultTable), one predicate decides whether the OSSDs may be on (Scanner::ossd_may_be_on), and
// only one function writes the OSSD (Scanner::apply_ossd); every other path leaves it off.

#include "rs4/scanner/faults.h"
#include "rs4/scanner/field_evaluation.h"
#include "rs4/scanner/parameter_set.h"
#include "rs4/scanner/scene.h"

#include <boost/outcome/std_result.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace rs4sim::rs4::scanner {

using TimePoint = std::chrono::steady_clock::time_point;

// Restart pulse rule ([RS4 manual §4.3]: "zwischen 0,12 und 5 Sekunden"), both ends included.
inline constexpr std::chrono::milliseconds kRestartPulseMin{120};
inline constexpr std::chrono::milliseconds kRestartPulseMax{5000};

struct ScannerConfig {                              // simulation settings, not RS4 parameters
  std::chrono::milliseconds boot_duration{30000};   // [RS4 manual §7.1.1] "nach ca. 30 Sekunden"
  std::chrono::milliseconds scan_period{40};        // 25 revolutions per second
  std::uint8_t contamination_warning_percent = 50;  // → warning (0x54), warning output
  std::uint8_t contamination_fault_percent = 80;    // → fault (0x53), OSSD off
  Identity identity{0x00012345, 0x0004, 1, 0};      // serial number, type, firmware
};

// The scanner model's operating state; values as option 1 bits 2..4 of its telegrams
// ([RS4 manual §5.2.3], protocol::Option1State), kOff = powered off (no telegrams).
enum class ScannerState : std::uint8_t {
  kOff = 0,
  kInitialisation = 1,
  kMeasuring = 2,
  kConfiguration = 3,
  kError = 4,
};
const char* to_string(ScannerState s) noexcept;

struct Rs4Event {  // content of 0x53 / 0x54 ([RS4 manual §5.2.3.2, §5.2.3.3])
  enum class Kind : std::uint8_t { kError, kWarning };
  Kind kind = Kind::kError;
  std::uint16_t number = 0;
  std::uint16_t parameter = 0;
  std::uint16_t function = 0;
  TimePoint at{};
};

struct ScanResult {
  std::uint32_t scan_number = 0;  // value of the scan counter ([RS4 manual §5.2.3.4])
  TimePoint at{};
  Contour contour{};  // mm per segment, kNoEchoMm = no echo
  FieldFlags first;   // the active (first selected) pair
  FieldFlags second;  // pair being left in a switch-over
  std::uint8_t first_pair = 0;
  std::uint8_t second_pair = 0;  // 0 = no switch-over in this scan
};

struct ScannerStatus {  // everything the cyclic byte and option 2/3 need
  ScannerState state = ScannerState::kOff;
  bool ossd = false;
  bool warning_output = false;              // true = set/active (the adapter inverts,
                                            // [RS4 manual §5.1.1])
  bool protective_violated = false;         // option 2 bit 0 / input bit 1
  bool warning_violated = false;            // option 2 bit 1 / input bit 0
  bool contamination_warning = false;       // option 2 bit 2
  bool fault = false;                       // option 2 bit 3
  bool restart_interlock = false;           // option 2 bit 4
  bool second_protective_violated = false;  // option 2 bit 5
  bool second_warning_violated = false;     // option 2 bit 6
  std::uint8_t first_pair = 0;              // option 3 bits 0..2
  std::uint8_t second_pair = 0;             // option 3 bits 3..5
  bool restart_held = false;
  std::uint8_t contamination_percent = 0;
  std::uint32_t scan_counter = 0;
};

// The scanner's own LEDs as far as the manual describes them: LED3 red while the restart input
// is held ([RS4 manual §4.3] "Während der Betätigung der Restart-Taste … leuchtet rot"), LED5
// yellow blinking while the window is contaminated ([RS4 manual §8.3] "Eine blinkende gelbe
// LED5 zeigt ,Fensterverschmutzung' an"); their other states are not modelled
// [docs/decisions.md#rs4-scanner-leds].
struct ScannerLeds {
  bool led3_red = false;
  bool led5_yellow_blinking = false;
  friend bool operator==(const ScannerLeds&, const ScannerLeds&) = default;
};

struct ScannerCounters {
  std::uint64_t scans = 0;
  std::uint64_t boots = 0;
  std::uint64_t ossd_off_switches = 0;
  std::uint64_t restart_accepted = 0;
  std::uint64_t restart_too_short = 0;
  std::uint64_t restart_too_long = 0;
  std::uint64_t restart_without_effect = 0;  // accepted pulse that changed nothing
  std::uint64_t field_pair_switches = 0;
  std::uint64_t faults = 0;
  std::uint64_t events_dropped = 0;
};

class Scanner {
 public:
  static constexpr std::size_t kEventCapacity = 16;

  explicit Scanner(ScannerConfig config = {});  // powered off, factory parameters

  // Lifecycle. Every input first runs the scans due up to `now`.
  void power_on(TimePoint now);
  void power_off(TimePoint now);
  void power_cycle(TimePoint now);
  void advance(TimePoint now);
  [[nodiscard]] TimePoint next_deadline() const noexcept;

  // Inputs from the adapter / the harness.
  void set_restart_input(bool high, TimePoint now);
  void select_field_pair(std::uint8_t pair, TimePoint now);
  void set_contamination(std::uint8_t percent, TimePoint now);  // clamped to 100 %
  boost::outcome_v2::std_result<void> inject_fault(Fault fault, TimePoint now);
  boost::outcome_v2::std_result<void> clear_fault(Fault fault, TimePoint now);
  // A telegram the RS4 does not know: the RS4 goes into its error state ([RS4 manual §5.2.2]
  // "(RS4 geht in Fehlerzustand)"): OSSD off, the error (0x0501, parameter `code`) as an
  // event, latched until a restart pulse like any fault whose cause is gone.
  void unknown_command(std::uint8_t code, TimePoint now);
  Scene& edit_scene(TimePoint now);  // edits take effect at the next scan

  // Parametrisation ([RS4 manual §7.1.2]: OSSD off while the set changes). The identity stays the
  // device's; use merge_download() to keep passwords on a proxy download.
  boost::outcome_v2::std_result<void> enter_configuration(TimePoint now);
  boost::outcome_v2::std_result<void> set_parameters(const ParameterSet& set, TimePoint now);
  boost::outcome_v2::std_result<void> leave_configuration(TimePoint now);
  // [RS4 manual §7.1, §7.2]: when a proxy upload/download fails the device falls back to factory
  // settings. Keeps identity and user passwords; a running scanner (also one in
  // configuration: the reset ends it) makes a new start.
  void reset_to_factory_default(TimePoint now);
  // True while the set equals the factory default apart from identity and passwords
  // (what the proxy reports as CONFIG_SET_TO_DEFAULT, [RS4 manual §7.1, §7.2] scenario 1).
  [[nodiscard]] bool factory_settings() const;
  [[nodiscard]] std::uint32_t parameter_checksum() const;  // CRC-32 of encode(parameters())
  // CRC-32 of encode_for_transfer(parameters()): the set CRC the proxy compares.
  [[nodiscard]] std::uint32_t transfer_checksum() const;
  // Counts every write of the set (set_parameters, reset_to_factory_default) since the
  // device was made; kept over power cycles, wraps at 0xFFFF (reported by the proxy's
  // IDENTIFY, [docs/proxy-protocol.md]).
  [[nodiscard]] std::uint16_t change_counter() const noexcept { return change_counter_; }

  // Observation.
  [[nodiscard]] bool ossd() const noexcept { return ossd_; }
  [[nodiscard]] ScannerStatus status() const noexcept;
  [[nodiscard]] ScannerLeds leds() const noexcept;  // all dark while powered off
  [[nodiscard]] const ScanResult& last_scan() const noexcept { return last_; }
  [[nodiscard]] const ParameterSet& parameters() const noexcept { return params_; }
  [[nodiscard]] const FaultTable& faults() const noexcept { return faults_; }
  [[nodiscard]] const ScannerCounters& counters() const noexcept { return counters_; }
  [[nodiscard]] const Scene& scene() const noexcept { return scene_; }
  [[nodiscard]] std::size_t pending_events() const noexcept { return event_count_; }
  std::optional<Rs4Event> pop_event() noexcept;
  [[nodiscard]] std::size_t heap_bytes() const noexcept { return scene_.heap_bytes(); }

 private:
  // --- the safety rule -----------------------------------------------------------
  [[nodiscard]] bool ossd_may_be_on() const noexcept;
  void apply_ossd() noexcept;

  // --- lifecycle and scans (scanner.cpp) ------------------------------------------
  void start_measuring(TimePoint at);
  void run_scans(TimePoint now);
  void do_scan(TimePoint at);
  [[nodiscard]] bool scanning() const noexcept;
  [[nodiscard]] bool warning_output() const noexcept;

  // --- inputs (scanner_inputs.cpp) -------------------------------------------------
  void on_restart_pulse(TimePoint at);
  void request_pair(std::uint8_t pair, TimePoint at);
  void raise_fault(Fault fault, std::uint16_t parameter, TimePoint at);
  void update_contamination(TimePoint at);
  void push_event(const Rs4Event& e) noexcept;
  [[nodiscard]] bool any_fault_present() const noexcept;
  [[nodiscard]] bool any_fault_latched() const noexcept;

  ScannerConfig config_;
  ParameterSet params_;
  std::uint16_t change_counter_ = 0;
  Scene scene_;
  std::uint64_t rendered_revision_ = ~std::uint64_t{0};

  ScannerState state_ = ScannerState::kOff;
  TimePoint boot_end_{};
  TimePoint next_scan_{};
  bool steady_ = false;  // the next due scans change nothing but counters
  bool ossd_ = false;

  bool restart_held_ = false;
  TimePoint restart_pressed_at_{};
  bool interlock_ = false;            // start/restart interlock waits for a pulse
  std::uint32_t violated_scans_ = 0;  // consecutive, saturates at T/40 ms
  bool scanned_since_start_ = false;

  std::uint8_t requested_pair_ = 1;  // the input (SF1..4 / cyclic bits 0..2)
  std::uint8_t active_pair_ = 0;
  std::uint8_t second_pair_ = 0;  // pair being left until the next scan

  std::uint8_t contamination_percent_ = 0;
  bool contamination_warning_ = false;
  FaultTable faults_{};

  ScanResult last_;
  std::uint32_t scan_counter_ = 0;
  std::array<Rs4Event, kEventCapacity> events_{};
  std::size_t event_head_ = 0;
  std::size_t event_count_ = 0;
  ScannerCounters counters_;
};

}  // namespace rs4sim::rs4::scanner
