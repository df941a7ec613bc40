#pragma once
// The virtual Optoscan Polaris barrier on RS485 Modbus RTU [Polaris manual §8], a
// stream::ByteDevice on the injected clock.
//   slave:  frames cut by t3.5 of silence; FC 3/4 read the data block from the configured
//           start address; CRC error or another function -> exception 0x07 (the manual)
//           or the standard reaction (silence / 0x01) with nak_on_error = false; other
//           addresses and broadcast reads are ignored. The answer leaves when the scan in
//           progress at the end of the request ends. EXTENSION: FC 3/4/6/16 on the
//           configuration registers (polaris/config_registers.h) set the options and start
//           auto-calibration, 0.4 s x N beams [Polaris manual §7.2], during which data reads
//           get exception 0x06 (DECISION).
//   master: an FC 16 push of the data block every scan_time; the slave's answer is framed,
//           counted and ignored [Polaris manual §8.1.1].
// The scene (interrupted beams) and the fault controls are set from outside (API, tests).

#include "modbus/rtu_frame.h"
#include "polaris/config_registers.h"
#include "polaris/counters.h"
#include "polaris/faults.h"
#include "polaris/data_modes.h"
#include "polaris/leds.h"
#include "polaris/options.h"
#include "polaris/scene.h"
#include "polaris/storage.h"
#include "stream/byte_device.h"
#include "stream/idle_gap_framer.h"
#include "stream/transmit_fault.h"

#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <system_error>
#include <vector>

namespace rs4sim::polaris {

class Device final : public stream::ByteDevice {
 public:
  // `options` must pass validate().
  explicit Device(Options options);

  [[nodiscard]] stream::LineSettings line_settings() const override;
  void on_bytes(std::span<const std::uint8_t> bytes, stream::TimePoint now) override;
  void on_time(stream::TimePoint now) override;
  [[nodiscard]] std::optional<stream::TimePoint> next_deadline() const override;
  std::optional<std::vector<std::uint8_t>> take_transmit() override;

  // The scene: physical beams (1 = next to the connector cap) interrupted from `now` on;
  // an error (nothing changed) when a beam is 0 or beyond the barrier.
  std::error_code set_interrupted(std::span<const std::uint16_t> beams, stream::TimePoint now);
  void set_faults(const Faults& faults) { faults_ = faults; }

  // Auto-calibration [Polaris manual §7.2]: the autocal input, SW1 or the PC tool's
  // "Auto-Cal" (the Modbus command register does the same). It lasts calibration_time()
  // from `now`; errc::device_or_resource_busy (nothing changed) while one runs,
  // ConfigError::kBeamsInterrupted (nothing changed) with a beam interrupted ("Make sure that
  // there is no material to be detected or other obstacles in the detection area"). It
  // leaves manual adjustment. A beam interrupted while it runs makes it fail: it ends
  // there, not counted (calibrations_failed()). Wakes the link.
  std::error_code start_calibration(stream::TimePoint now);
  // The SW1 contact (or the autocal input) closed or opened at `now` [Polaris manual §7.2]:
  // opened after 0.5..3 s closed starts an auto-calibration (its error returned), after more
  // than 3 s enters manual adjustment ("keeping the SW1 contact closed for more than 3
  // seconds"), after less than 0.5 s does nothing.
  std::error_code set_sw1(bool closed, stream::TimePoint now);
  // Manual adjustment: auto-calibration switched off (SW1 held > 3 s, the command register's
  // 2); the trimmer it hands over to is not modelled.
  [[nodiscard]] bool manual_adjustment() const { return manual_adjustment_; }
  [[nodiscard]] std::uint16_t calibrations_failed() const { return calibrations_failed_; }
  // The TX and RX LEDs at `now` [Polaris manual §5.1] [Polaris manual §7.2].
  [[nodiscard]] Leds leds(stream::TimePoint now) const;
  // The data storage's memory [Polaris manual §7.4.2] (polaris/storage.h).
  [[nodiscard]] const Storage& storage() const { return storage_; }
  // Calibrating at `now`: started at or before it and not yet ended (end exclusive).
  [[nodiscard]] bool calibrating(stream::TimePoint now) const;
  [[nodiscard]] std::optional<stream::TimePoint> calibration_end() const { return calibration_end_; }
  // Auto-calibrations completed by the last call (wraps at 65535, like its register).
  [[nodiscard]] std::uint16_t calibrations() const { return calibrations_; }
  // "approximately ... 0.4 seconds * N beams" [Polaris manual §7.2].
  [[nodiscard]] stream::Duration calibration_time() const;

  // One scan from `now` on: `response_time` (0: the model's maximum response time of
  // `column`); ConfigError::kInvalidOptions (nothing changed) when Options::validate()
  // refuses it. What was due before `now` happens first; scans then restart at `now`.
  std::error_code set_response_time(stream::Duration response_time, ResponseColumn column,
                                    stream::TimePoint now);
  [[nodiscard]] stream::Duration scan() const { return scan_; }
  [[nodiscard]] const Options& options() const { return options_; }
  [[nodiscard]] const Counters& counters() const { return counters_; }
  [[nodiscard]] const Faults& faults() const { return faults_; }
  [[nodiscard]] std::vector<std::uint16_t> data_block() const;
  [[nodiscard]] std::vector<Object> objects() const;
  // The interrupted physical beams, ascending.
  [[nodiscard]] std::vector<std::uint16_t> interrupted() const;
  // PN1: an object is detected. PN2: two objects (object detection), or a hole seen for
  // pn2_filter scans (hole detection) [Polaris manual §3].
  [[nodiscard]] bool pn1() const;
  [[nodiscard]] bool pn2(stream::TimePoint now) const;

 private:
  void start(stream::TimePoint now);
  void advance(stream::TimePoint now);
  void handle(const stream::GapFrame& frame);
  void handle_request(const modbus::RtuFrame& request, stream::TimePoint end);
  void handle_read(const modbus::RtuFrame& request, stream::TimePoint end);
  // An incorrect function: exception 07, or `standard` with nak_on_error = false.
  void refuse_function(const modbus::RtuFrame& request, stream::TimePoint end,
                       modbus::ExceptionCode standard);
  // FC 6/16 to us: applied or refused, answered.
  void handle_write(const modbus::RtuFrame& request, stream::TimePoint end);
  void finish_calibration(stream::TimePoint now);
  void begin_calibration(stream::TimePoint start);
  // Data words for a transmission (an answer to a data read, a push): the storage then resets.
  [[nodiscard]] std::vector<std::uint16_t> transmit_block();
  void answer(const modbus::RtuFrame& reply, stream::TimePoint end);
  void push_data(stream::TimePoint due);
  void schedule(std::vector<std::uint8_t> bytes, stream::TimePoint due);
  [[nodiscard]] stream::TimePoint scan_end_after(stream::TimePoint t) const;

  Options options_;
  stream::Duration scan_;
  stream::IdleGapFramer framer_;
  Scene scene_;
  stream::TimePoint scene_since_{};
  std::optional<stream::TimePoint> epoch_;
  std::optional<stream::TimePoint> next_push_;
  std::optional<stream::TimePoint> calibration_end_;
  std::uint16_t calibrations_ = 0;
  std::uint16_t calibrations_failed_ = 0;
  bool manual_adjustment_ = false;
  std::optional<stream::TimePoint> sw1_closed_;
  Storage storage_;
  stream::TransmitQueue pending_;
  std::deque<std::vector<std::uint8_t>> transmit_;
  Counters counters_;
  Faults faults_;
};

}  // namespace rs4sim::polaris
