#pragma once
// PROFIsafe F-host driver, V1 and V2 ([PROFIsafe V1.30 F-Device behaviour] [IEC 61784-3-3 safety
// PDU]; rules in docs/profisafe.md).
//
// Sans-I/O: each bus cycle the master asks request(now) for the F-output PDU and hands
// the slave's answer to on_pdu(). The host sends consecutive number n until a valid answer
// echoes n, then advances. Its watchdog (F_WD_Time) runs from the first send of n.
//
// Any fault (CRC2, consecutive number, own watchdog, device-reported CE_CRC / WD_timeout)
// passivates the device: input() yields the substitute value 0 and the host sends fail-safe
// output values 0 with activate_FV. Once a valid answer without fault bits arrives again,
// ack_req() becomes true; ack_rei() (the user acknowledgement) reintegrates. At start-up the
// device is reintegrated automatically on the first healthy answer (DECISION).
//
// V2: the number is virtual (24 bit, not sent); each new PDU flips Toggle_h, and a valid answer
// carries Toggle_d = Toggle_h and a CRC2 over the same number. The first PDU, and the first
// after any fault, restarts the number at 0 with R_cons_nr (DECISION).

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

struct FHostConfig {
  FParameters params{};        // F-parameters of the device (par_crc is computed in)
  std::size_t data_size = 1;   // F-data bytes each way
  Crc2Variant crc2_variant{};  // V1 CRC2 rule (UNCERTAIN, see pdu.h)
};

enum class FHostState : std::uint8_t {
  kStartup,      // passivated, waiting for the first healthy answer (automatic reintegration)
  kRun,          // process values flow
  kPassivated,   // a fault was seen; waiting for healthy communication
  kAckRequired,  // communication healthy again: ACK_REQ raised, waiting for ACK_REI
};
// "startup", "run", "passivated", "ack-required": the API's and the event stream's word,
// also the one logs print.
[[nodiscard]] std::string_view to_token(FHostState s) noexcept;
[[nodiscard]] const char* to_string(FHostState s) noexcept;  // to_token() as a C string

enum class FHostEvent : std::uint8_t {
  kValid,        // valid answer to the current number
  kStale,        // valid answer echoing the previous number (device not there yet)
  kCrcError,     // size or CRC2 wrong
  kNumberError,  // any other consecutive number
  kDeviceFault,  // valid answer carrying CE_CRC or WD_timeout
  kNotExpected,  // nothing was sent yet
};
[[nodiscard]] const char* to_string(FHostEvent e) noexcept;

struct FHostCounters {
  std::uint64_t requests = 0, answers = 0, stale = 0;
  std::uint64_t crc_errors = 0, number_errors = 0, watchdog_timeouts = 0;
  std::uint64_t device_ce_crc = 0, device_wd_timeout = 0;
  std::uint64_t passivations = 0, reintegrations = 0;
};

class FHost {
 public:
  // Throws std::invalid_argument unless the parameters are a V1 (2-byte CRC2) or V2 (3- or
  // 4-byte CRC2) connection and the data size is 1..kMaxDataSize.
  explicit FHost(FHostConfig config);

  // The F-parameter block for Set_Prm, with ParameterFaults applied.
  [[nodiscard]] std::array<std::uint8_t, kFParametersSize> parameter_block() const noexcept;
  [[nodiscard]] std::uint16_t crc1() const noexcept { return pdu_config_.crc1; }

  // Process output values (host → device), taken into the next new PDU.
  void set_output(std::span<const std::uint8_t> data);
  void set_activate_fv(bool on) noexcept { user_activate_fv_ = on; }

  // The F-output PDU for this bus cycle (empty while muted by fault injection).
  [[nodiscard]] std::span<const std::uint8_t> request(TimePoint now);
  FHostEvent on_pdu(std::span<const std::uint8_t> pdu, TimePoint now);
  void on_time(TimePoint now);
  [[nodiscard]] std::optional<TimePoint> next_deadline() const noexcept;

  // Process image of the device's inputs: its data in kRun, else the substitute value 0.
  [[nodiscard]] std::span<const std::uint8_t> input() const noexcept;
  [[nodiscard]] bool passivated() const noexcept { return state_ != FHostState::kRun; }
  [[nodiscard]] bool ack_req() const noexcept { return state_ == FHostState::kAckRequired; }
  void ack_rei() noexcept;  // user acknowledgement; only effective while ack_req()
  [[nodiscard]] FHostState state() const noexcept { return state_; }
  // V1: the consecutive number in flight; V2: the virtual consecutive number.
  [[nodiscard]] std::uint32_t number() const noexcept { return number_; }
  [[nodiscard]] ProtocolVersion version() const noexcept { return pdu_config_.version; }
  [[nodiscard]] std::uint8_t last_status() const noexcept { return last_status_; }
  [[nodiscard]] const FHostCounters& counters() const noexcept { return counters_; }
  [[nodiscard]] const PduCheck& last_check() const noexcept { return last_check_; }
  PduFaults& faults() noexcept { return faults_; }
  ParameterFaults& parameter_faults() noexcept { return parameter_faults_; }

 private:
  void passivate();
  void build_new_pdu(TimePoint now);
  void handle_valid(const PduCheck& check);
  void advance_number();
  FHostEvent classify_v1();
  FHostEvent classify_v2(std::span<const std::uint8_t> pdu);

  FHostConfig config_;
  PduConfig pdu_config_{};
  FHostState state_ = FHostState::kStartup;
  std::uint32_t number_ = 0;           // number of the PDU in flight
  std::uint32_t previous_number_ = 0;  // V2: the number before it
  bool started_ = false;               // a PDU was built
  bool toggle_h_ = true;               // V2: Toggle_h of the PDU in flight (flips per new PDU)
  bool restart_ = true;                // V2: the next new PDU restarts at 0 with R_cons_nr
  bool outstanding_ = false;           // a PDU with number_ waits for its answer
  bool user_activate_fv_ = false;
  std::uint8_t last_status_ = 0;
  std::optional<TimePoint> watchdog_deadline_;
  std::array<std::uint8_t, kMaxDataSize> output_{};
  std::array<std::uint8_t, kMaxDataSize> input_{};
  std::array<std::uint8_t, kMaxPduSize> pdu_{};
  std::array<std::uint8_t, kMaxPduSize> previous_pdu_{};
  std::array<std::uint8_t, kMaxPduSize> wire_{};
  bool has_previous_ = false;
  PduCheck last_check_{};
  FHostCounters counters_{};
  PduFaults faults_{};
  ParameterFaults parameter_faults_{};
};

}  // namespace rs4sim::profisafe
