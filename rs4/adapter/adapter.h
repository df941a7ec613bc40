#pragma once
// The PROFIsafe adapter of the RS4/PROFIsafe
// ([RS4 manual §4.5, §5.1, §7.1, §7.2, §5.2, §5.2.3, §5.3, §6.2, §6.3];
// [RS4 manual §4.4, §4.5, §5, §7]): what makes rs4sim behave like the real device on the bus.
//
// rs4::adapter::Adapter implements dp::slave::SlaveApplication. The owner (rs4/device) builds a
// dp::slave::Slave at station_address() around it, forwards the slave's calls, honours
// wants_link_down_until() (PROFI_CMD_RESET, [RS4 manual §5.2.2]) and drives
// on_time()/next_deadline(). Sans-I/O: time comes in, no clock reads, no threads
// ([docs/design.md#principles]).
//
//   cyclic  5-byte F-output PDU → profisafe::FDevice → output byte → Scanner (restart,
//           field pair) ; Scanner state → input byte (compose_input_byte, the only place
//           where the OSSD bit can become 1) → FDevice (status, CRC2) → 5-byte F-input PDU
//   acyclic slot 0, index 2/3, block protocol (rs4/protocol/block.h) → adapter command
//           or RS4 command → answer queue → READ blocks with the flow-control byte
//   alarms  update alarm ([RS4 manual §5.3.1]) and diagnosis alarms coming/going
//     ([RS4 manual §5.3.2]) via SlaveControl
//
// Decisions the manual leaves open are listed in docs/rs4-adapter.md.

#include "dp/slave/slave_application.h"
#include "gsd/device_gsd.h"
#include "profisafe/f_device.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/adapter/error_memory.h"
#include "rs4/adapter/pc_link.h"
#include "rs4/adapter/proxy_session.h"
#include "rs4/adapter/release_gate.h"
#include "rs4/adapter/rs4_commands.h"
#include "rs4/adapter/rs4_gsd.h"
#include "rs4/protocol/adapter_answer.h"
#include "rs4/protocol/adapter_command.h"
#include "rs4/protocol/adapter_error.h"
#include "rs4/protocol/alarm.h"
#include "rs4/protocol/block.h"
#include "rs4/scanner/scanner.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <system_error>
#include <vector>

namespace rs4sim::rs4::adapter {

using TimePoint = dp::TimePoint;
using Duration = dp::Duration;
using std::chrono::milliseconds;

// ---- configuration constants of the project's GSD (docs/gsd.md, gsd/device_gsd.h) -----
// One source: the layout constants beside the built-in GSD (ident, F_Dest_Add and slave
// settings: rs4/adapter/rs4_gsd.h); tests/rs4/adapter proves that what gsd::configure
// produces for the shipped GSD is accepted.
inline constexpr const auto& kRealConfig = gsd::kRs4simCfg;  // C0 84 84: 5 bytes out/in
inline constexpr const auto& kFBlockHeader = gsd::kRs4simFBlockHeader;
inline constexpr std::size_t kPduSize = 5;  // PROFIsafe V1: data, status, number, CRC2 hi/lo

struct AdapterConfig {
  scanner::ScannerConfig scanner{};
  AddressSwitches switches{};            // factory setting 4 ([RS4 manual §4.5])
  milliseconds init_duration{2500};      // LED steady 2–3 s ([RS4 manual §4.4])
  milliseconds reset_link_down{2000};    // PROFI_CMD_RESET: link down ≈2 s ([RS4 manual §5.2.2])
  milliseconds field_pair_release{500};  // valid pair again → OSSD after ≈500 ms
                                         // ([RS4 manual §5.1.2])
  milliseconds going_alarm_delay{500};   // ≥500 ms without error → going alarm
                                         // ([RS4 manual §5.3.2])
  // "Reaktionszeit PROFIsafe-Adapter 10 ms" [RS4 manual, technical data; §6.6]: a change of the
  // RS4's OSSDs and field bits reaches the cyclic input byte this much later. 0: at once.
  milliseconds response_time{10};
  // The RS4 takes time to process a command: "bis zu 2 Minuten" [RS4 manual §5.2.1]. Its answer
  // (and its effect) comes this much after the command's last WRITE block; 0: at once. The
  // manual gives only the bound; one scan (40 ms) is the default
  // [docs/decisions.md#rs4-command-time].
  milliseconds rs4_command_time{40};
  // Accepted by the RS4's password rule while both user passwords are empty (the factory
  // state): the same rule and default as on its RS232 (rs4_commands.h, docs/rs232.md).
  std::array<std::uint8_t, 8> factory_password = kFactoryPassword;
  std::size_t read_buffers = 4;            // answers awaiting a READ per channel (0x2A05)
  bool check_reserved_output_bits = true;  // output bits 5..3 ≠ 0 → 0x2419, byte not applied
  std::size_t event_buffer = 8;       // second buffer: 0x53/0x54 for 0x92 ([RS4 manual §5.2.2])
  protocol::VersionAnswer version{};  // PROFI_CMD_GET_VERSION bytes
  // The GSD whose Chk_Cfg and User_Prm_Data layout Set_Prm/Chk_Cfg are checked against
  // (rs4_gsd.h); nullptr: the built-in one.
  std::shared_ptr<const GsdProfile> gsd;
};

// Status LED of the adapter ([RS4 manual §4.4]).
enum class LedState : std::uint8_t {
  kDark,          // powered off
  kSteadyInit,    // steady 2–3 s after power-on / adapter reset
  kFastBlink,     // ≈5 Hz: ready for the PROFIBUS connection
  kOffConnected,  // off: in data exchange with the class 1 master
  kSteadyFault,   // fault: steady for more than 3 s (invalid address switches)
  kSlowBlink,     // fault: blinking slower than 5 Hz (F-parameters refused)
};
[[nodiscard]] const char* to_string(LedState s) noexcept;  // for people: "off (connected)"
// "dark", "steady-init", "fast-blink", "off-connected", "steady-fault", "slow-blink" (the
// API's and the event stream's word).
[[nodiscard]] std::string_view to_token(LedState s) noexcept;

// How the LED shows a state: lit for `on` of every `period`; period 0 = steady (lit when `on`
// is non-zero). Fast blink ≈5 Hz as the manual says; the fault blink is "slower than ≈5 Hz"
// [RS4 manual §4.4], modelled at 1 Hz [docs/decisions.md#rs4-led-blink].
struct LedPattern {
  milliseconds on{0};
  milliseconds period{0};
  friend bool operator==(const LedPattern&, const LedPattern&) = default;
};
[[nodiscard]] LedPattern led_pattern(LedState s) noexcept;
// Whether the LED is lit `in_state` after the state began (a blink starts lit).
[[nodiscard]] bool led_lit(LedState s, Duration in_state) noexcept;

// Where the Proxy-Enable / Proxy-Request / OSSD-release logic of [RS4 manual §7.1, §7.2] stands.
enum class ProxyPhase : std::uint8_t {
  kWaitRs4,      // RS4 not yet operational since power-on: OSSD bit 0
  kRequested,    // Proxy-Request set, no check running
  kSyncRunning,  // the proxy reported "sync started": Proxy-Request 0
  kDone,         // check passed (or not needed): release allowed
};
[[nodiscard]] const char* to_string(ProxyPhase p) noexcept;  // for people: "wait for RS4"
// "wait-rs4", "requested", "sync-running", "done" (the API's and the event stream's word).
[[nodiscard]] std::string_view to_token(ProxyPhase p) noexcept;

struct AdapterCounters {
  std::uint64_t cyclic_exchanges = 0;
  std::uint64_t prm_accepted = 0, prm_refused = 0, cfg_refused = 0;
  std::uint64_t writes = 0, reads = 0, writes_ignored = 0, dpv1_rejected = 0;
  std::uint64_t adapter_commands = 0, rs4_commands = 0, rejected_commands = 0;
  std::uint64_t alarms_submitted = 0, alarms_refused = 0;
  std::uint64_t field_pair_errors = 0, resets = 0;
};

// Errors of the control API (not wire errors).
enum class AdapterApiError : std::uint8_t {
  kPoweredOff = 1,   // the device has no power
  kNoSyncRequested,  // sync started while Proxy-Request is 0
  kNoSyncRunning,    // sync succeeded/failed without sync started
};
[[nodiscard]] std::string_view to_string(AdapterApiError e) noexcept;
constexpr const char* error_category_name(AdapterApiError) noexcept { return "rs4.adapter.api"; }
inline std::error_code make_error_code(AdapterApiError e) noexcept {
  return codec::make_error_code_of(e);
}

// Everything an observer (gRPC service, CLI, tests) sees in one snapshot.
struct AdapterView {
  bool powered = false;
  std::optional<std::uint8_t> station_address;
  std::uint16_t f_dest_add = 0;
  LedState led = LedState::kDark;
  ProxyPhase proxy = ProxyPhase::kWaitRs4;
  bool proxy_enable = false;
  bool pc_adapter_attached = false;
  bool connected = false;       // class 1 data exchange
  std::uint8_t input_byte = 0;  // the process byte before FDevice
  InputBits input;
  std::uint8_t output_byte = 0;  // the process byte FDevice delivered
  OutputBits output;
  std::array<std::uint8_t, kPduSize> input_pdu{};
  std::array<std::uint8_t, kPduSize> output_pdu{};
  profisafe::FDeviceState fdevice = profisafe::FDeviceState::kNoParameters;
  scanner::ScannerState rs4 = scanner::ScannerState::kOff;
  bool field_pair_error = false;
  bool error_active = false;  // diagnosis alarm "coming" outstanding
};

class Adapter final : public dp::slave::SlaveApplication {
 public:
  explicit Adapter(AdapterConfig config = {});  // powered off

  // ---- power and switches ([RS4 manual §4.5, §7.1, §7.2]) ---------------------------------------
  void power_on(TimePoint now);   // reads the address switches
  void power_off(TimePoint now);  // error memory lost
  void power_cycle(TimePoint now);
  // Takes effect at the next power-on / adapter reset, as on the device.
  // The GSD the adapter is checked against (AdapterConfig::gsd, else the built-in one).
  [[nodiscard]] const GsdProfile& gsd() const noexcept {
    return config_.gsd ? *config_.gsd : builtin_profile();
  }
  void set_address_switches(AddressSwitches s) noexcept { config_.switches = s; }
  [[nodiscard]] AddressSwitches address_switches() const noexcept { return config_.switches; }
  // The station address read at power-on; nullopt while off or when the switches are invalid.
  [[nodiscard]] std::optional<std::uint8_t> station_address() const noexcept { return address_; }
  // While set, the owner keeps the DP link down (PROFI_CMD_RESET, [RS4 manual §5.2.2]).
  [[nodiscard]] std::optional<TimePoint> wants_link_down_until() const noexcept;

  // ---- scene and user actions -----------------------------------------------------------
  // Scene, faults, contamination. After a change, run on_time(now) (the owner's loop does)
  // so that the input byte follows; the byte on the wire is composed fresh in read_inputs.
  scanner::Scanner& scanner() noexcept { return scanner_; }
  [[nodiscard]] const scanner::Scanner& scanner() const noexcept { return scanner_; }
  // Device exchange ([RS4 manual §7.1, §7.2] scenario 4): another RS4 unit, with its own identity
  // and factory settings, is mounted on this adapter (the boot duration stays the
  // simulation's). Only while powered off, as on site; false (nothing changed) while powered.
  bool exchange_scanner(const scanner::ScannerConfig& unit);
  void set_restart_button(bool pressed, TimePoint now);  // button on X1 ([RS4 manual §2.3, §2.4])
  // The button on X1 held ([RS4 manual §4.3]); the scanner's restart input is this or bit 3.
  [[nodiscard]] bool restart_button() const noexcept { return restart_button_; }
  void attach_pc_adapter(TimePoint now);                 // reed contact of X5
                                                         // ([RS4 manual §7.1, §7.2])
  void detach_pc_adapter(TimePoint now);
  // Input bit 3 ([RS4 manual §5.1.1]): the RS4's RS232 is switched through to the PC adapter
  // (attached and no sync running); rs4/rs232 answers only then.
  [[nodiscard]] bool rs232_switched_through() const noexcept { return pc_.switched_through(); }
  // Called with every 0x53/0x54 event the RS4 emits, as the adapter collects it (the RS232
  // port behind the PC adapter sends them too); an empty function removes the listener.
  void set_rs4_event_listener(std::function<void(const scanner::Rs4Event&)> listener) {
    event_listener_ = std::move(listener);
  }

  // ---- proxy hooks (EXTENSION, [RS4 manual §7.1, §7.2] [docs/proxy-protocol.md]) ----------------
  // The adapter side of the Proxy-FB sync. PROFI_CMD_PROXY_BEGIN (0x98) and _END (0x99) from
  // the class 1 master drive them; the harness and tests may call them directly.
  std::error_code proxy_sync_started(TimePoint now);    // Proxy-Request → 0, flow state 011
  std::error_code proxy_sync_succeeded(TimePoint now);  // check done → OSSD release
  // The sync failed: `error` (0 or a table 5.3-3 proxy error) into the error memory with a
  // diagnosis alarm, the RS4 back to factory settings, Proxy-Request → 1 (reason retry).
  std::error_code proxy_sync_failed(TimePoint now, std::uint16_t error = 0);
  [[nodiscard]] const ProxySession& proxy_session() const noexcept { return proxy_; }

  // ---- observation ------------------------------------------------------------------------
  [[nodiscard]] AdapterView view() const;
  [[nodiscard]] bool ossd_bit() const noexcept { return (input_byte_ & kInputOssd) != 0; }
  [[nodiscard]] std::uint8_t input_byte() const noexcept { return input_byte_; }
  [[nodiscard]] std::uint8_t output_byte() const noexcept { return output_byte_; }
  [[nodiscard]] LedState led() const noexcept;
  // Whether the LED is lit at `now`: led_lit(led(), now - the moment the LED entered its state),
  // so a blink follows led_pattern() from its start ([docs/decisions.md#rs4-led-blink]).
  [[nodiscard]] bool led_lit(TimePoint now) const noexcept;
  [[nodiscard]] ProxyPhase proxy_phase() const noexcept;
  // The parameter-check gate of [RS4 manual §7.1, §7.2]: true once the OSSD bit may follow the RS4.
  [[nodiscard]] bool released() const noexcept { return gate_.released(); }
  [[nodiscard]] protocol::FlowState flow_state(dp::slave::AcyclicChannel ch) const noexcept;
  [[nodiscard]] std::uint8_t flow_byte(dp::slave::AcyclicChannel ch, bool payload) const noexcept;
  [[nodiscard]] const ErrorMemory& error_memory() const noexcept { return errors_; }
  [[nodiscard]] const AdapterCounters& counters() const noexcept { return counters_; }
  [[nodiscard]] const profisafe::FDevice& fdevice() const noexcept { return fdevice_; }
  profisafe::PduFaults& safety_faults() noexcept { return fdevice_.faults(); }
  [[nodiscard]] std::size_t pending_answers(dp::slave::AcyclicChannel ch) const noexcept;
  [[nodiscard]] std::size_t buffered_events() const noexcept { return event_buffer_.size(); }

  // ---- dp::slave::SlaveApplication ----------------------------------------------------------
  void on_attach(dp::slave::SlaveControl& control) override { control_ = &control; }
  dp::slave::PrmVerdict check_parameters(const dp::pdu::SetPrm& prm, TimePoint now) override;
  dp::slave::CfgVerdict check_config(std::span<const std::uint8_t> cfg, bool user_check,
                                     TimePoint now) override;
  [[nodiscard]] std::span<const std::uint8_t> real_config() const override { return kRealConfig; }
  void on_outputs(std::span<const std::uint8_t> outputs, TimePoint now) override;
  void on_outputs_cleared(dp::slave::OutputClear why, TimePoint now) override;
  void read_inputs(std::span<std::uint8_t> inputs, TimePoint now) override;
  void on_state_change(dp::slave::State from, dp::slave::State to, dp::slave::TransitionReason why,
                       TimePoint now) override;
  dp::slave::AcyclicResult on_acyclic(const dp::slave::AcyclicRequest& req, TimePoint now) override;
  void on_c2_event(dp::slave::C2Event ev, std::uint8_t master, TimePoint now) override;
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override;
  void on_time(TimePoint now) override;

 private:
  struct Channel {  // one per acyclic channel (C1, C2)
    protocol::BlockAssembler assembler{protocol::Direction::kWrite};
    struct Processing {  // an RS4 command the RS4 is still working on
      TimePoint due;
      std::vector<std::uint8_t> command;
    };
    std::deque<Processing> processing;              // in order of arrival
    std::deque<std::vector<std::uint8_t>> answers;  // results awaiting READ
    protocol::BlockSplitter reading;                // the answer being read out
    void clear();
  };
  struct Forwarding {  // PROFI_CMD_GET_RS4_DATA state ([RS4 manual §5.2.2])
    std::uint8_t mask = 0;
    bool permanent = false;
    std::optional<std::vector<std::uint8_t>> telegram;  // first buffer: 0x23 / 0x14
    std::optional<std::uint32_t> last_scan;  // scan captured last (nullopt: take the next)
  };

  // The RS4 signals as the adapter sees them, `response_time` after the RS4
  // ([RS4 manual, technical data]): sampled from the scanner.
  struct Rs4Signals {
    bool ossd = false;
    bool warning_output = false;
    bool protective = false;
    bool warning = false;
    friend bool operator==(const Rs4Signals&, const Rs4Signals&) = default;
  };
  Rs4Signals sample_rs4() const noexcept;
  void follow_rs4_signals(TimePoint now);  // feeds and drains signal_line_
  void finish_processing(TimePoint now);   // RS4 commands whose processing time is over
  void submit_rs4_command(std::span<const std::uint8_t> command, Channel& ch, TimePoint now);
  // adapter.cpp: power, start-up, parameters
  void start_adapter(TimePoint now, bool keep_errors);
  void enter_data_exchange(TimePoint now);
  // adapter_cyclic.cpp: the process bytes and the [RS4 manual §7.1, §7.2] logic
  void apply_output_byte(std::uint8_t out, TimePoint now);
  void apply_field_pair(std::uint8_t pair, TimePoint now);
  void update_rs4_phase(TimePoint now);
  void refresh_input(TimePoint now);
  // Input bit 5: an error of the RS4 or of the adapter is present ([RS4 manual §5.1.1]).
  [[nodiscard]] bool error_present() const noexcept;
  [[nodiscard]] bool ossd_release_allowed(TimePoint now) const noexcept;
  [[nodiscard]] std::uint8_t compose_input_byte(TimePoint now) const noexcept;
  void drive_restart_input(TimePoint now);
  // adapter_acyclic.cpp
  dp::slave::AcyclicResult on_write(const dp::slave::AcyclicRequest& req, Channel& ch,
                                    TimePoint now);
  dp::slave::AcyclicResult on_read(const dp::slave::AcyclicRequest& req, Channel& ch,
                                   TimePoint now);
  void execute(std::span<const std::uint8_t> command, dp::slave::AcyclicChannel which, Channel& ch,
               TimePoint now);
  void execute_adapter_command(const protocol::WriteCommand& cmd, Channel& ch, TimePoint now);
  [[nodiscard]] std::vector<std::uint8_t> execute_rs4_command(std::span<const std::uint8_t> command,
                                                              TimePoint now);
  [[nodiscard]] std::optional<std::vector<std::uint8_t>> execute_setting_command(
      std::span<const std::uint8_t> command, const protocol::DecodedPrefix& prefix, TimePoint now);
  void report_rs4_refusal(std::span<const std::uint8_t> answer,
                          std::span<const std::uint8_t> command, TimePoint now);
  [[nodiscard]] bool ready_for_write(dp::slave::AcyclicChannel which) const noexcept;
  [[nodiscard]] Channel& channel(dp::slave::AcyclicChannel which) noexcept;
  [[nodiscard]] const Channel& channel(dp::slave::AcyclicChannel which) const noexcept;
  // adapter_proxy.cpp: the device side of the proxy sync ([docs/proxy-protocol.md])
  void request_sync(protocol::SyncReason why);
  void switch_through_after_sync(TimePoint now);
  void fail_sync(std::uint16_t error, TimePoint now);
  void proxy_begin(Channel& ch, TimePoint now);
  void proxy_end(const protocol::ProxyEndCommand& end, Channel& ch, TimePoint now);
  void abort_on_user_command(std::span<const std::uint8_t> command, dp::slave::AcyclicChannel which,
                             TimePoint now);
  [[nodiscard]] std::vector<std::uint8_t> transfer(std::span<const std::uint8_t> command,
                                                   TimePoint now, bool authorised);
  // adapter_events.cpp: RS4 events, forwarding, error memory, alarms
  void collect_rs4(TimePoint now);
  void capture_forwarding();
  std::optional<std::vector<std::uint8_t>> take_forwarded();
  void adapter_error(protocol::AdapterError e, TimePoint now);
  void report_error(std::uint16_t uc2_error, std::uint16_t uc1_error, TimePoint now);
  void submit_diagnosis_alarm(protocol::AlarmDifferentiation d);
  void check_going_alarm(TimePoint now);

  AdapterConfig config_;
  dp::slave::SlaveControl* control_ = nullptr;
  scanner::Scanner scanner_;
  profisafe::FDevice fdevice_;
  ErrorMemory errors_;

  bool powered_ = false;
  std::optional<std::uint8_t> address_;
  std::optional<TimePoint> init_end_;  // adapter initialising until then ([RS4 manual §2.3, §2.4])
  std::optional<TimePoint> link_down_until_;
  bool connected_ = false;    // class 1 in Data_Exch
  bool prm_refused_ = false;  // F-parameters refused (LED slow blink)

  // [RS4 manual §7.1, §7.2] proxy logic
  ReleaseGate gate_;    // RS4 up, Proxy-Request, Proxy-Enable, released, verify open
  ProxySession proxy_;  // sync running, reason, direction, the open download
  PcLink pc_;  // reed contact, bit 3 switched through, pending until the sync's last answer
  LedState led_state_ = LedState::kDark;  // the LED's state as last seen by track_led()
  TimePoint led_since_{};                 // when it entered that state
  void track_led(TimePoint now) noexcept;

  // [RS4 manual §5.1] cyclic
  std::uint8_t input_byte_ = 0;
  std::uint8_t output_byte_ = 0;
  std::array<std::uint8_t, kPduSize> output_pdu_{};
  std::array<std::uint8_t, kPduSize> input_pdu_{};  // the F-input PDU sent last
  bool restart_bus_ = false;
  bool restart_button_ = false;
  bool restart_driven_ = false;
  // The RS4 signals as the adapter sees them: the delay line and the value in force.
  std::deque<std::pair<TimePoint, Rs4Signals>> signal_line_;
  Rs4Signals seen_;
  bool field_pair_error_ = false;
  std::optional<TimePoint> field_pair_release_at_;
  std::uint8_t field_pair_ = 1;

  // [RS4 manual §5.2] acyclic
  Channel c1_, c2_;
  Forwarding forwarding_;
  std::deque<std::vector<std::uint8_t>> event_buffer_;  // second buffer: 0x53 / 0x54

  // [RS4 manual §5.3] alarms
  bool error_active_ = false;
  bool adapter_error_active_ = false;  // a one-shot adapter error not yet gone: input bit 5
  std::optional<std::uint8_t> inconsistent_output_;  // the output byte that gave 0x2419
  TimePoint last_error_at_{};
  std::uint16_t last_uc2_error_ = 0, last_uc1_error_ = 0;
  std::vector<std::uint16_t> reported_;  // errors reported coming since going/connect

  AdapterCounters counters_;
  std::function<void(const scanner::Rs4Event&)> event_listener_;
};

}  // namespace rs4sim::rs4::adapter
