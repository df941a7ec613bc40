#pragma once
// A whole simulated segment around one RS4/PROFIsafe: our class 1 master configured from
// the GSD, a PROFIsafe F-host driving the 5-byte cyclic PDUs, and an Rs4Device, on a
// link::MemoryBus with a ManualClock. Used by `rs4sim demo`, `rs4sim run --device rs4
// --link memory`, the integration tests and the benchmarks.
//
// Each master cycle (CycleCompleted) the F-host sees the RS4's last F-input PDU and
// builds the next F-output PDU around the process output byte (restart, Proxy-Enable,
// field pair, [RS4 manual §5.1.2]); its input() is the unwrapped input byte, 0 while passivated.

#include "dp/link/memory_bus.h"
#include "dp/master/master.h"
#include "rs4/device/rs4_device.h"
#include "rs4/device/rs4_master.h"

#include <boost/outcome/std_result.hpp>

#include <functional>
#include <memory>
#include <vector>

namespace rs4sim::rs4::device {

struct Rs4SegmentConfig {
  Rs4DeviceConfig device{};   // address switches, boot time, scanner …
  Rs4MasterOptions master{};  // station address (must match the switches)
  std::uint8_t master_address = 1;
  dp::BaudRate baud = dp::BaudRate::k1M5;
  dp::Duration cycle_target = std::chrono::milliseconds(10);
  dp::link::MemoryBusConfig bus{};
  std::uint8_t output_byte = 0x01;  // initial process output: field pair 1
  bool auto_ack_rei = false;        // acknowledge every ACK_REQ at once
  // Keep every master event for events()/take_events() (tests, demos that read them). A run
  // whose events nobody takes sets it false: then only the events of a DPV1 request being
  // awaited are kept, and memory stays flat however long the simulated time.
  bool keep_events = true;
};

class Rs4Segment {
 public:
  // Throws std::system_error / std::invalid_argument for a bad configuration
  // (GSD override errors as std::invalid_argument with the gsd message).
  explicit Rs4Segment(const Rs4SegmentConfig& config);

  [[nodiscard]] dp::ManualClock& clock() { return clock_; }
  [[nodiscard]] dp::TimePoint now() const { return clock_.now(); }
  [[nodiscard]] dp::link::MemoryBus& bus() { return *bus_; }
  [[nodiscard]] dp::master::Master& master() { return *master_; }
  [[nodiscard]] const dp::master::Master& master() const { return *master_; }
  [[nodiscard]] Rs4Device& device() { return *device_; }
  [[nodiscard]] const Rs4Device& device() const { return *device_; }
  [[nodiscard]] profisafe::FHost& fhost() { return *fhost_; }
  [[nodiscard]] const profisafe::FHost& fhost() const { return *fhost_; }
  [[nodiscard]] const Rs4MasterEntry& entry() const { return entry_; }
  [[nodiscard]] std::uint8_t rs4_address() const { return entry_.slave.address; }

  void power_on() { device_->power_on(now()); }
  void power_off() { device_->power_off(now()); }

  // Process output byte ([RS4 manual §5.1.2]) sent through the F-host from the next cycle on.
  void set_output_byte(std::uint8_t out);
  [[nodiscard]] std::uint8_t output_byte() const { return output_; }
  // Unwrapped process input byte ([RS4 manual §5.1.1]); 0 while the F-host is passivated.
  [[nodiscard]] std::uint8_t input_byte() const;
  [[nodiscard]] bool in_data_exchange() const;
  void ack_rei() { fhost_->ack_rei(); }
  // Acknowledge every ACK_REQ at once (the config's auto_ack_rei), or leave it to ack_rei().
  void set_auto_ack_rei(bool on) { auto_ack_rei_ = on; }
  [[nodiscard]] bool auto_ack_rei() const { return auto_ack_rei_; }

  // Simulated time runs until done() holds (checked after every bus event) or `timeout`
  // passes; returns done().
  bool run_until(const std::function<bool()>& done, dp::Duration timeout);
  void run_for(dp::Duration d);

  // DPV1 C1 Write then wait for its result (slot 0, index 2, [RS4 manual §5.2]); nullopt on
  // timeout.
  std::optional<dp::master::Dpv1Result> write_record(
      std::span<const std::uint8_t> record, dp::Duration timeout = std::chrono::seconds(2));
  std::optional<dp::master::Dpv1Result> read_record(std::uint8_t length = 240,
                                                    dp::Duration timeout = std::chrono::seconds(2));

  // One command through the block protocol ([RS4 manual §5.2.1]): WRITE it as a single block
  // (payload
  // ≤ 236 bytes), then READ blocks until the last one (0xFFFF) and return the joined
  // answer payload. A READ without payload (answer not ready, [RS4 manual §5.2.1] flow bit 1 = 0)
  // is repeated every cycle up to `timeout`. Errors: the DPV1 error of a failed WRITE/READ,
  // std::errc::timed_out, or the block decoder's error.
  boost::outcome_v2::std_result<std::vector<std::uint8_t>> command(
      std::span<const std::uint8_t> payload, dp::Duration timeout = std::chrono::seconds(2));

  [[nodiscard]] const std::vector<dp::master::MasterEvent>& events() const { return events_; }
  std::vector<dp::master::MasterEvent> take_events();

  // Called with every master event as it is collected, inside the bus's run (after the
  // F-host's step for a CycleCompleted): the seam for a component that lives on the
  // segment's cycles, such as the demo's parameter proxy (app/demos/demo_proxy.h). It may
  // submit DPV1 requests to master(). One observer; an empty function removes it.
  using Observer = std::function<void(const dp::master::MasterEvent&)>;
  void set_observer(Observer observer) { observer_ = std::move(observer); }

 private:
  void collect();
  void safety_cycle();
  std::optional<dp::master::Dpv1Result> await(dp::master::Dpv1RequestId id, dp::Duration timeout);

  dp::ManualClock clock_;
  Rs4MasterEntry entry_;
  std::unique_ptr<Rs4Device> device_;
  std::unique_ptr<dp::master::Master> master_;
  std::unique_ptr<profisafe::FHost> fhost_;
  std::unique_ptr<dp::link::MemoryBus> bus_;
  std::uint8_t output_ = 0x01;
  bool auto_ack_rei_ = false;
  bool keep_events_ = true;
  int awaiting_ = 0;  // await() calls under way: their events are kept
  std::vector<dp::master::MasterEvent> events_;
  std::vector<dp::master::MasterEvent> scratch_;
  Observer observer_;
};

}  // namespace rs4sim::rs4::device
