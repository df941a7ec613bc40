#pragma once
// The virtual ReeR METRON Receiver on its RS-485 line, as a stream::ByteDevice: slave line
// mode (answers the host's 13 commands, Equation 3's reply delay) or standard line mode
// (sends reports by its reporting mode) [METRON manual "Serial line management"]. Sans-I/O:
// time comes in with every call, frames leave through take_transmit() when due.

#include "metron/counters.h"
#include "metron/faults.h"
#include "metron/options.h"
#include "metron/scene.h"
#include "metron/slave_handler.h"
#include "metron/slave_receiver.h"
#include "metron/slave_state.h"
#include "metron/standard_line.h"
#include "stream/byte_device.h"
#include "stream/transmit_fault.h"

#include <deque>
#include <optional>
#include <span>
#include <system_error>
#include <vector>

namespace rs4sim::metron {

class Device final : public stream::ByteDevice {
 public:
  // `options` must have passed validate().
  explicit Device(Options options);
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  [[nodiscard]] stream::LineSettings line_settings() const override;
  void on_bytes(std::span<const std::uint8_t> bytes, stream::TimePoint now) override;
  void on_time(stream::TimePoint now) override;
  [[nodiscard]] std::optional<stream::TimePoint> next_deadline() const override;
  std::optional<std::vector<std::uint8_t>> take_transmit() override;

  // A byte that failed its parity check (a serial link that sees parity errors passes such
  // bytes here): the whole message it belongs to gets no reply [METRON manual "No node"].
  void on_byte_with_parity_error(std::uint8_t byte, stream::TimePoint now);
  // The link's damaged character (stream::ByteDevice): a parity error, handled as above.
  void on_damaged_byte(std::uint8_t byte, stream::TimePoint now) override {
    on_byte_with_parity_error(byte, now);
  }

  // The scene. Beam numbers from 1; the input drives input-related reporting.
  [[nodiscard]] const Scene& scene() const { return scene_; }
  // The given beams interrupted, the others free; a beam outside 1..beams() changes nothing
  // and is refused (SceneError::kNoSuchBeam).
  std::error_code set_interrupted(std::span<const std::uint16_t> beams);
  void set_beam(std::uint16_t beam, bool interrupted);
  void set_input(bool high);
  void set_synchronised(bool synchronised);

  [[nodiscard]] const Faults& faults() const { return faults_; }
  // Wakes the link: a late answer's due time may move.
  void set_faults(const Faults& f) {
    faults_ = f;
    wake();
  }
  // The scan cycle and Equation 3's t_response from now on [METRON manual "Slave line
  // mode"]: "" or Options::validate()'s sentence (nothing changed). A reply already due
  // keeps its time; the next report cycle follows the new scan cycle. Wakes the link.
  std::string set_timing(stream::Duration scan_cycle, stream::Duration t_response);
  [[nodiscard]] const Options& options() const { return options_; }
  [[nodiscard]] const SlaveState& slave_state() const { return state_; }
  [[nodiscard]] bool ossd_on() const;
  [[nodiscard]] bool resetting(stream::TimePoint now) const { return now < reset_until_; }
  [[nodiscard]] Counters counters() const;

 private:
  void process_messages(stream::TimePoint now);
  void react(const SlaveMessage& m, const Reaction& r, stream::TimePoint now);
  void count(const Reaction& r);
  void queue(Outgoing frame);
  void release(stream::TimePoint now);
  void scene_changed();

  Options options_;
  Scene scene_;
  SlaveState state_;
  SlaveReceiver receiver_;
  StandardLine standard_;
  Faults faults_;
  Counters counters_;
  bool started_ = false;
  stream::TimePoint reset_until_{};
  stream::TransmitQueue pending_;
  std::deque<std::vector<std::uint8_t>> transmit_;
  std::vector<Outgoing> scratch_;
};

}  // namespace rs4sim::metron
