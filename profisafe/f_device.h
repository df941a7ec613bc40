#pragma once
// PROFIsafe F-device driver ([PROFIsafe V1.30 F-Device behaviour]; rules in docs/profisafe.md).
//
// Sans-I/O: the DP slave hands each received F-output PDU to on_pdu() with `now`, then
// sends response(). The application sets its input data with set_input() and reads the
// host's output data with output(). One predicate, sends_process_values(), decides
// whether real data (not fail-safe values 0) go out and come in.
//
// V1 and V2 ([IEC 61784-3-3 safety PDU], rules in docs/profisafe.md): the F-parameters select
// the protocol. V1 sends the consecutive number (1 byte) and a 2-byte CRC2; V2 sends no number:
// Toggle_h in the control byte marks a new PDU, the virtual consecutive number (24 bit) goes
// into the 3- or 4-byte CRC2 on both sides, R_cons_nr restarts it at 0 (answered with
// cons_nr_R), and the answer carries Toggle_d = the host's Toggle_h.
//
// States: kNoParameters (no valid F-parameters: all-zero PDU) → kStartup (valid
// F-parameters, fail-safe values until the first valid host PDU) → kRun ⇄ kFault
// (CE_CRC / WD_timeout latched, fail-safe values; cleared by the second valid new host PDU
// after the fault, so the host has seen the fault status once).

#include "profisafe/f_parameters.h"
#include "profisafe/faults.h"
#include "profisafe/pdu.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace rs4sim::profisafe {

using TimePoint = std::chrono::steady_clock::time_point;

struct FDeviceConfig {
  DeviceProfile profile{};     // fixed values, ranges, own F_Dest_Add
  std::size_t data_size = 1;   // F-data bytes each way
  Crc2Variant crc2_variant{};  // V1 CRC2 rule (UNCERTAIN, see pdu.h)
};

enum class FDeviceState : std::uint8_t { kNoParameters, kStartup, kRun, kFault };
// "no-parameters", "startup", "run", "fault": the API's and the event stream's word, also the
// one logs print.
[[nodiscard]] std::string_view to_token(FDeviceState s) noexcept;
[[nodiscard]] const char* to_string(FDeviceState s) noexcept;  // to_token() as a C string

// What on_pdu() made of a host PDU.
enum class FDeviceEvent : std::uint8_t {
  kIgnored,      // no valid F-parameters: not evaluated
  kNew,          // valid PDU with a new consecutive number (watchdog restarted)
  kRepeat,       // valid PDU repeating the last number (nothing changes)
  kCrcError,     // size or CRC2 wrong → CE_CRC, fail-safe values
  kNumberError,  // consecutive number neither last nor next → CE_CRC, fail-safe values
                 // (V2: CRC2 fails with the expected virtual number but holds with the
                 // current or the one after the next: a repeated or skipped number)
};
[[nodiscard]] const char* to_string(FDeviceEvent e) noexcept;

struct FDeviceCounters {
  std::uint64_t pdus = 0, new_pdus = 0, repeats = 0;
  std::uint64_t crc_errors = 0, number_errors = 0, watchdog_timeouts = 0;
  std::uint64_t parameter_errors = 0;
};

class FDevice {
 public:
  // Throws std::invalid_argument unless the profile is V1 (F_Par_Version 0, 2-byte CRC2) or
  // V2 (F_Par_Version 1, 3- or 4-byte CRC2) and data_size is 1..kMaxDataSize.
  explicit FDevice(FDeviceConfig config);

  // Set_Prm: the F-parameter block (10 bytes). Valid → kStartup; otherwise the fault is
  // kept and the device stays in / returns to kNoParameters.
  Validation set_parameters(std::span<const std::uint8_t> block);
  [[nodiscard]] const Validation& last_validation() const noexcept { return validation_; }
  // The standard diagnosis of the last F-parameters (64..71, 0 when accepted; f_parameters.h).
  [[nodiscard]] std::uint8_t diagnosis() const noexcept {
    return standard_diagnosis(validation_.fault);
  }

  // The application's process input (device → host). Size must equal data_size.
  void set_input(std::span<const std::uint8_t> data);

  FDeviceEvent on_pdu(std::span<const std::uint8_t> pdu, TimePoint now);
  void on_time(TimePoint now);
  [[nodiscard]] std::optional<TimePoint> next_deadline() const noexcept;

  // The PDU to send now (empty while muted by fault injection).
  [[nodiscard]] std::span<const std::uint8_t> response();

  // THE predicate: real data flow (both directions) only in kRun without activate_FV.
  [[nodiscard]] bool sends_process_values() const noexcept;

  // Host output data for the application: the last new valid PDU's data, or 0 (fail-safe).
  [[nodiscard]] std::span<const std::uint8_t> output() const noexcept;
  [[nodiscard]] std::uint8_t status_byte() const noexcept;
  [[nodiscard]] FDeviceState state() const noexcept { return state_; }
  // V1: the last accepted consecutive number; V2: the virtual consecutive number.
  [[nodiscard]] std::uint32_t last_number() const noexcept { return number_; }
  [[nodiscard]] ProtocolVersion version() const noexcept { return pdu_config_.version; }
  [[nodiscard]] const FDeviceCounters& counters() const noexcept { return counters_; }
  [[nodiscard]] const PduCheck& last_check() const noexcept { return last_check_; }
  PduFaults& faults() noexcept { return faults_; }
  [[nodiscard]] const PduFaults& faults() const noexcept { return faults_; }

 private:
  void enter_fault(std::uint8_t bit);
  FDeviceEvent classify_v1(std::span<const std::uint8_t> pdu);
  FDeviceEvent classify_v2(std::span<const std::uint8_t> pdu);
  bool adopt_neighbour(std::span<const std::uint8_t> pdu, std::uint32_t expected, bool toggle);
  void accept_new(const PduCheck& check, TimePoint now);
  void build_response();
  void apply_faults();

  FDeviceConfig config_;
  PduConfig pdu_config_{};
  FDeviceState state_ = FDeviceState::kNoParameters;
  Validation validation_{};
  std::uint8_t fault_bits_ = 0;
  bool fault_reported_ = false;
  bool activate_fv_ = false;
  std::uint32_t number_ = 0;     // V1 consecutive number / V2 virtual number accepted last
  std::uint32_t candidate_ = 0;  // the number of the PDU being accepted
  bool toggle_ = true;           // V2: Toggle_h of the PDU accepted last (none: 1, so 0 is new)
  bool candidate_toggle_ = false;
  bool candidate_reset_ = false;
  bool cons_nr_reset_ = false;  // V2: the PDU accepted last carried R_cons_nr
  std::optional<TimePoint> watchdog_deadline_;
  std::array<std::uint8_t, kMaxDataSize> input_{};
  std::array<std::uint8_t, kMaxDataSize> output_{};
  std::array<std::uint8_t, kMaxPduSize> response_{};
  std::array<std::uint8_t, kMaxPduSize> sent_{};  // what response() returned last
  std::array<std::uint8_t, kMaxPduSize> wire_{};  // response with faults applied
  std::size_t response_size_ = 0;
  std::uint16_t wd_time_ms_ = 0;
  bool has_sent_ = false;
  bool synced_ = false;  // a first valid PDU was accepted since the F-parameters were set
  PduCheck last_check_{};
  FDeviceCounters counters_{};
  PduFaults faults_{};
};

}  // namespace rs4sim::profisafe
