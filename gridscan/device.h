#pragma once
// The virtual CEDES GridScan/Pro SI with RS485 interface (type suffix RC) as a sans-I/O
// stream::ByteDevice ([GridScan manual §9, §10, §11]).
//
// Power-up: Info: Get version (0xA0, SeqCnt 0) at once, Data: Reduced state (0xB0,
// SeqCnt 1) when ready (Options::ready_time); requests before that are dropped. Then scan
// cycles of t_CYCLE start at the ready instant: a request completed (by idle gap) during a
// cycle is answered after the cycle's end, one request per cycle ([GridScan manual §11]);
// a streaming message follows the answer. A request with a wrong SeqCnt, ID, sync or CRC
// gets no reply, except the communication test 0x23, which reports them
// ([GridScan manual §10.2, §10.3]). Every dropped frame is counted by reason.

#include "gridscan/counters.h"
#include "gridscan/faults.h"
#include "gridscan/frame.h"
#include "gridscan/leds.h"
#include "gridscan/options.h"
#include "gridscan/scene.h"
#include "stream/byte_device.h"
#include "stream/idle_gap_framer.h"

#include <cstdint>
#include <deque>
#include <optional>
#include <string_view>
#include <vector>

namespace rs4sim::gridscan {

enum class PowerState : std::uint8_t { kOff, kStarting, kReady };
// "off", "starting", "ready" (the API's and the event stream's word).
[[nodiscard]] std::string_view to_token(PowerState p) noexcept;

class Device final : public stream::ByteDevice {
 public:
  // `options` must have passed validate(). The device powers up at the first call from
  // its link (on_time or on_bytes) unless power_off() came first.
  explicit Device(const Options& options);

  [[nodiscard]] stream::LineSettings line_settings() const override { return kLineSettings; }
  void on_bytes(std::span<const std::uint8_t> bytes, stream::TimePoint now) override;
  void on_time(stream::TimePoint now) override;
  [[nodiscard]] std::optional<stream::TimePoint> next_deadline() const override;
  std::optional<std::vector<std::uint8_t>> take_transmit() override;

  // Power: the mains of both edges. Configuration and the alignment flag survive.
  void power_on(stream::TimePoint now);
  void power_off();

  // The scene (what the elements see). Takes effect at the next scan.
  [[nodiscard]] const Scene& scene() const { return scene_; }
  void set_scene(const Scene& s) { scene_ = s; }
  void set_door_position(unsigned n) { scene_.door_position = n < elements() ? n : elements(); }
  void set_blocked(std::uint64_t elements_mask) {
    scene_.blocked = elements_mask & element_mask(elements());
  }
  // The objects as element numbers 1..elements() (Scene::set_interrupted), as every device.
  std::error_code set_interrupted(std::span<const std::uint16_t> numbers) {
    return scene_.set_interrupted(numbers, elements());
  }
  [[nodiscard]] std::vector<std::uint16_t> interrupted() const { return scene_.interrupted(); }
  void set_soiling(std::uint8_t level) { scene_.soiling = level > 3 ? 3 : level; }
  void set_internal_failure(bool on) { scene_.internal_failure = on; }
  void set_alignment_value(std::uint16_t v) { scene_.alignment_value = v; }

  [[nodiscard]] const Faults& faults() const { return faults_; }
  // Wakes the link: the answer time (transmit.late) moves the deadline.
  void set_faults(const Faults& f) {
    faults_ = f;
    wake();
  }

  // Observation.
  [[nodiscard]] PowerState power() const { return power_; }
  [[nodiscard]] CommMode mode() const { return mode_; }
  [[nodiscard]] Configuration configuration() const { return configuration_; }
  [[nodiscard]] unsigned elements() const { return options_.elements; }
  // t_CYCLE from the next power-up on (the cycles run from the ready instant
  // [GridScan manual §11]; a running grid is not moved): "" or why not, check_cycle()'s
  // sentence for a value outside the manual's band.
  std::string set_cycle(stream::Duration cycle);
  [[nodiscard]] const Options& options() const { return options_; }
  // t_CYCLE of the running power-up.
  [[nodiscard]] stream::Duration cycle() const { return cycle_; }
  [[nodiscard]] bool alignment_active() const { return alignment_active_; }
  [[nodiscard]] const Counters& counters() const { return counters_; }
  [[nodiscard]] Leds leds(stream::TimePoint now) const;
  [[nodiscard]] StateReport current_report() const;
  // What the elements report in a scan (the faults' stuck elements applied).
  [[nodiscard]] StateReport scanned_report() const;

 private:
  struct Pending {
    RawFrame request;
    stream::TimePoint cycle_end;
  };
  struct Reaction {
    std::optional<Payload> payload;  // nullopt: no answer
    bool restart = false;
  };

  // device.cpp: power, timing, framing, transmission.
  void start_if_waiting(stream::TimePoint now);
  void power_up(stream::TimePoint now);
  void advance(stream::TimePoint now);
  void become_ready(stream::TimePoint t);
  void receive(const stream::GapFrame& f);
  void tick(stream::TimePoint cycle_end, stream::TimePoint now);
  void send_cycle_messages();
  [[nodiscard]] std::optional<stream::TimePoint> tick_deadline() const;
  [[nodiscard]] bool periodic() const;
  [[nodiscard]] stream::TimePoint cycle_end_after(stream::TimePoint t) const;
  void send(std::uint8_t id, std::uint8_t seq, const Payload& payload);
  void send_answer(CommandId c, std::uint8_t request_seq, const Payload& payload);

  // device_commands.cpp: the manual's commands.
  void answer_request(const RawFrame& raw, stream::TimePoint cycle_end);
  Reaction execute(CommandId c, stream::TimePoint cycle_end);
  Reaction set_mode(CommMode m);
  Reaction allow_change(stream::TimePoint cycle_end);
  Reaction set_configuration(Configuration target, stream::TimePoint cycle_end);
  [[nodiscard]] Payload state_payload(bool full);
  [[nodiscard]] StateReport test_report() const;
  [[nodiscard]] bool window_over(stream::TimePoint t) const;

  Options options_;
  Configuration configuration_;
  Scene scene_;
  Faults faults_;
  Counters counters_;
  stream::IdleGapFramer framer_;
  std::deque<std::vector<std::uint8_t>> transmit_;
  std::optional<Frame> last_sent_;  // before the faults (what an inserted frame repeats)

  bool waiting_for_start_ = true;
  PowerState power_ = PowerState::kOff;
  stream::TimePoint power_up_at_{};
  stream::TimePoint ready_at_{};
  stream::Duration cycle_{};
  stream::TimePoint next_end_{};  // the next cycle end with work to do
  std::optional<Pending> pending_;

  CommMode mode_ = CommMode::kPolling;
  std::uint8_t last_seq_ = 0;    // the last SeqCnt sent on the request/response channel
  std::uint8_t stream_seq_ = 0;  // the separate streaming SeqCnt ([GridScan manual §9.2.2])
  unsigned standby_door_ = 0;    // door position reported in stand-by (the last known)
  bool change_allowed_ = false;  // 0x50 succeeded
  bool config_read_ = false;     // 0x53 after 0x50
  bool test_pending_ = false;    // the next state message shows all elements interrupted
  bool alignment_armed_ = false;
  bool alignment_active_ = false;
};

}  // namespace rs4sim::gridscan
