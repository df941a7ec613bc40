#pragma once
// The master side of a segment of RS4/PROFIsafe scanners as one dp::Station, sans-I/O:
// our class 1 master with one entry per RS4 from the GSD (rs4_master.h) and one PROFIsafe
// F-host per RS4. Any link runs it (MemoryBus on the manual clock, StationRunner on a
// pty/serial/UDP link) exactly as it runs a device.
//
// Every master cycle (CycleCompleted), right inside the link's call, each F-host sees its
// RS4's last F-input PDU and builds the next F-output PDU around the process output byte
// (field pair, restart, Proxy-Enable bit 6, [RS4 manual §5.1.2]); the unwrapped input byte
// ([RS4 manual §5.1.1]) is 0 while the F-host is passivated. The F-host's watchdog keeps
// running while an RS4 is out of data exchange, so a lost RS4 passivates it; once the RS4
// answers again the F-host waits for ack_rei() (or auto_ack_rei). Changes are queued as
// Rs4MasterEvents and drained with take_events() after each link call, like
// dp::master::Master's own events.
//
// Cost: an RS4 is found by its address in an index; after a link call only the RS4s the
// master's events named (or all, after the safety cycle) are compared with what was last
// published, so a telegram costs O(1), a cycle O(RS4s) (issue 24).
//
// The seam for a parameter proxy (the Proxy-FB's job, [RS4 manual §7.1, §7.2]): it is
// driven by InputByteChanged (Proxy-Request, bit 2), by RecordResult (the outcome of its
// own DPV1 record read/write) and by MasterCycle (the time), and acts through
// set_proxy_enable(), write_record() and read_record() (slot 0, index 2, [RS4 manual §5.2]).

#include "dp/master/master.h"
#include "profisafe/f_host.h"
#include "rs4/device/rs4_master.h"

#include <boost/outcome/std_result.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace rs4sim::rs4::device {

struct Rs4MasterStationConfig {
  std::uint8_t master_address = 1;
  dp::master::BusParameters bus = dp::master::BusParameters::defaults_for(dp::BaudRate::k1M5);
  dp::Duration cycle_target = std::chrono::milliseconds(10);
  bool claim_token = true;               // [IEC 61158-4-3 token, bus start]
  std::vector<Rs4MasterOptions> slaves;  // one per RS4, polled in this order
  // Other DP slaves the same master polls after the RS4s (e.g. GSD stations configured from
  // their GSDs, app/runtime/master_gsd.h): no F-host, no events here; their state and I/O
  // through master(). The RS4 calls (view, set_output_byte, ...) do not know them.
  std::vector<dp::master::SlaveEntry> other_slaves;
  std::uint8_t output_byte = 0x01;       // initial process output of every RS4: field pair 1
  bool auto_ack_rei = false;             // acknowledge every ACK_REQ at once
  // Keep a copy of every dp::master event (alarms, diagnosis, …) for take_master_events(),
  // for an owner that needs more than the Rs4MasterEvents (e.g. a test harness, Rs4Segment).
  bool keep_master_events = false;
};

// What the master side knows of one RS4.
struct Rs4SlaveView {
  std::uint8_t address = 0;
  dp::master::PollState dp_state = dp::master::PollState::kStatusRequest;
  std::error_code dp_error;  // the current start-up / supervision fault, empty in data exchange
  profisafe::FHostState safety = profisafe::FHostState::kStartup;
  std::uint8_t f_diagnosis = 0;  // RS4 PROFIsafe diagnosis number, 0 = none ([RS4 manual §6.3])
  std::uint8_t input_byte = 0;   // unwrapped, 0 while passivated ([RS4 manual §5.1.1])
  std::uint8_t output_byte = 0;  // as given to the F-host ([RS4 manual §5.1.2])
  [[nodiscard]] bool data_exchange() const {
    return dp_state == dp::master::PollState::kDataExchange;
  }
};

// ---- events (drained with take_events) ---------------------------------------------------
// Data exchange entered or left, or the start-up failed for a new reason (not every
// start-up step: those repeat every cycle while an RS4 is not ready).
struct DpStateChanged {
  std::uint8_t address = 0;
  dp::master::PollState state = dp::master::PollState::kStatusRequest;
  std::error_code reason;  // why it left data exchange / why the start-up failed; may be empty
  [[nodiscard]] bool data_exchange() const { return state == dp::master::PollState::kDataExchange; }
};
struct SafetyStateChanged {
  std::uint8_t address = 0;
  profisafe::FHostState state = profisafe::FHostState::kStartup;
};
// The RS4's PROFIsafe diagnosis in its Slave_Diag changed ([RS4 manual §6.3]); 0 = none.
struct FDiagnosisChanged {
  std::uint8_t address = 0;
  std::uint8_t number = 0;
};
struct InputByteChanged {
  std::uint8_t address = 0;
  std::uint8_t previous = 0;
  std::uint8_t current = 0;
};
// Completion of write_record()/read_record() (or of any DPV1 request made on master()).
using RecordResult = dp::master::Dpv1Result;
// One master cycle ended at `now`: the clock tick of everything driven by the master side.
// Consecutive ticks not drained yet collapse into the newest one.
struct MasterCycle {
  std::uint64_t cycle = 0;
  dp::TimePoint now{};
};
using Rs4MasterEvent = std::variant<DpStateChanged, SafetyStateChanged, FDiagnosisChanged,
                                    InputByteChanged, RecordResult, MasterCycle>;

// The RS4's PROFIsafe diagnosis number from a Slave_Diag DU: the status PDU
// `05 81 00 00 nn` right after the 6 standard bytes ([RS4 manual §6.3, bytes 7..11]).
// nullopt when the DU does not carry it (shorter, or another block there).
[[nodiscard]] std::optional<std::uint8_t> f_diagnosis_number(std::span<const std::uint8_t> diag);

class Rs4MasterStation final : public dp::Station {
 public:
  // Throws std::invalid_argument (no slave at all, a GSD override error, a duplicate address) or
  // std::system_error (the master configuration does not validate).
  explicit Rs4MasterStation(const Rs4MasterStationConfig& config);
  ~Rs4MasterStation() override;
  Rs4MasterStation(const Rs4MasterStation&) = delete;
  Rs4MasterStation& operator=(const Rs4MasterStation&) = delete;

  // ---- dp::Station (forwarded to the master, then the safety cycle and the events) ----------
  [[nodiscard]] std::uint8_t address() const override { return master_->address(); }
  void on_telegram(const dp::fdl::Telegram& t, dp::TimePoint now) override;
  void on_time(dp::TimePoint now) override;
  [[nodiscard]] std::optional<dp::TimePoint> next_deadline() const override;
  std::optional<dp::fdl::Telegram> take_transmit() override;
  void on_malformed_frame(std::error_code why) override;

  // ---- per RS4 ----------------------------------------------------------------------------
  // The RS4s' addresses in configuration order (not the other_slaves).
  [[nodiscard]] std::vector<std::uint8_t> slave_addresses() const;
  // nullopt for an address that is not configured.
  [[nodiscard]] std::optional<Rs4SlaveView> view(std::uint8_t address) const;
  [[nodiscard]] std::uint8_t input_byte(std::uint8_t address) const;
  [[nodiscard]] bool in_data_exchange(std::uint8_t address) const;
  // Process output byte through the F-host from the next cycle on; false: unknown address.
  bool set_output_byte(std::uint8_t address, std::uint8_t out);
  // Bit 6 of the output byte; the RS4 evaluates it at its DP start-up ([RS4 manual §5.1.2]).
  bool set_proxy_enable(std::uint8_t address, bool on);
  bool ack_rei(std::uint8_t address);
  // Acknowledge every ACK_REQ at once (the config's auto_ack_rei), or leave it to ack_rei().
  void set_auto_ack_rei(bool on) { auto_ack_rei_ = on; }
  [[nodiscard]] bool auto_ack_rei() const { return auto_ack_rei_; }
  // DPV1 C1 record write/read on slot 0, index 2 ([RS4 manual §5.2]); the outcome comes as a
  // RecordResult event with the returned id. Errors now: those of dp::master::Master::write/read.
  boost::outcome_v2::std_result<dp::master::Dpv1RequestId> write_record(
      std::uint8_t address, std::span<const std::uint8_t> record);
  boost::outcome_v2::std_result<dp::master::Dpv1RequestId> read_record(std::uint8_t address,
                                                                       std::uint8_t length = 240);

  [[nodiscard]] dp::master::Master& master() { return *master_; }
  [[nodiscard]] const dp::master::Master& master() const { return *master_; }
  [[nodiscard]] const profisafe::FHost* fhost(std::uint8_t address) const;
  [[nodiscard]] const Rs4MasterEntry* entry(std::uint8_t address) const;

  // Moves all queued events to `out` (appends).
  void take_events(std::vector<Rs4MasterEvent>& out);
  // With keep_master_events: the master's own events since the last call (appends).
  void take_master_events(std::vector<dp::master::MasterEvent>& out);

 private:
  struct Slave;
  Slave* find(std::uint8_t address);
  [[nodiscard]] const Slave* find(std::uint8_t address) const;
  [[nodiscard]] Rs4SlaveView view_of(const Slave& s) const;
  void mark_changed(Slave* s);
  void after_call(dp::TimePoint now);
  void on_master_event(dp::master::MasterEvent& e, dp::TimePoint now);
  void safety_cycle(Slave& s, dp::TimePoint now);
  void publish_changes(Slave& s);

  std::unique_ptr<dp::master::Master> master_;
  std::vector<std::unique_ptr<Slave>> slaves_;  // configuration order
  std::array<std::int16_t, 128> index_{};       // address → slaves_ index, -1 if none
  std::vector<std::size_t> changed_;            // slaves_ indexes to publish
  bool all_changed_ = false;                    // the safety cycle ran: publish all
  bool auto_ack_rei_ = false;
  bool keep_master_events_ = false;
  std::vector<dp::master::MasterEvent> scratch_;
  std::vector<dp::master::MasterEvent> master_events_;
  std::vector<Rs4MasterEvent> events_;
};

}  // namespace rs4sim::rs4::device
