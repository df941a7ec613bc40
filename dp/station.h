#pragma once
// The sans-I/O contract between a PROFIBUS station core (slave or master) and a link.
//
// A link (memory bus, serial/pty, UDP) owns the bytes and the real time; a station core
// owns the protocol. The link:
//   1. decodes received bytes into telegrams (fdl::Decoder) and calls on_telegram();
//   2. calls on_time() when the station's next_deadline() has passed;
//   3. after either call, drains next_transmit() (or take_transmit()) and puts the telegrams
//      on the wire, each no earlier than its send_time() where the link honours that
//      (set_send_time_honoured);
//   4. reports frames its decoder rejected through on_malformed_frame();
//   5. installs a wake handler (set_wake_handler): a core whose transmit queue or
//      next_deadline() changed outside on_telegram()/on_time() (an application request,
//      a power-up) calls wake(), and the link drains and re-reads the deadline. Nobody
//      has to remember to tell the link (the shape of lely-core's can_net_set_next_func).
// Cores never block, sleep or read a clock; one event loop thread calls them.

#include "dp/fdl/telegram.h"
#include "dp/time/clock.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <system_error>

namespace rs4sim::dp {

class Station {
 public:
  virtual ~Station() = default;

  // This station's FDL address (0..126).
  [[nodiscard]] virtual std::uint8_t address() const = 0;

  // A well-formed telegram arrived on the bus (any destination: the core filters).
  virtual void on_telegram(const fdl::Telegram& t, TimePoint now) = 0;

  // Time has reached (or passed) next_deadline(); called at least once after start.
  virtual void on_time(TimePoint now) = 0;

  // When on_time() must be called next; nullopt = only when a telegram arrives.
  [[nodiscard]] virtual std::optional<TimePoint> next_deadline() const = 0;

  // The next telegram to send, if any. The link calls this until it returns nullopt.
  virtual std::optional<fdl::Telegram> take_transmit() = 0;

  // The same sequence as take_transmit(), handed out as a view instead of a copy: the next
  // telegram to send, nullptr when there is none (more). The telegram stays valid until the
  // next call on this station. A core that keeps its telegrams overrides this and hands out
  // its own storage (no copy per telegram on either side); the default moves take_transmit()
  // into `scratch`, which the link owns. A link drains with one of the two, not both.
  virtual const fdl::Telegram* next_transmit(fdl::Telegram& scratch) {
    auto t = take_transmit();
    if (!t) return nullptr;
    scratch = std::move(*t);
    return &scratch;
  }

  // When the telegram next_transmit()/take_transmit() handed out last may start on the wire
  // at the earliest; nullopt = at once. A link asks only after it said it honours it
  // (set_send_time_honoured(true)): it then holds the telegram until that time, or (a simulated
  // wire) starts it then. This lets a core hand out a telegram it already knows, such as a
  // master's next request after TID1 ([IEC 61158-4-3 bus parameters, timing]), in the same call
  // as the reply, instead of waiting for a deadline of its own. Default: nullopt.
  [[nodiscard]] virtual std::optional<TimePoint> send_time() const { return std::nullopt; }

  // Set by a link that honours send_time(). It is off unless the link the station is
  // attached to turns it on, so a wrapper station that does not forward it gets every telegram
  // from its inner core at the time it is due, as a link that ignores send_time() needs.
  void set_send_time_honoured(bool honoured) { send_time_honoured_ = honoured; }

  // The link's decoder rejected a frame under the receiver checks
  // ([IEC 61158-4-3 frame reception]): the station counts it (a slave shows it in its counters).
  // Default: ignored.
  virtual void on_malformed_frame(std::error_code why) { (void)why; }

  // How long (Tbit) a responder waits after a request before replying (min TSDR,
  // [IEC 61158-4-3 bus parameters, timing]); a slave reports what the master set with Set_Prm
  // byte 3. Default: 11 Tbit.
  [[nodiscard]] virtual std::uint16_t min_tsdr_bits() const { return 11; }

  // Installed by the link the station is attached to (one link at a time); an empty
  // handler detaches. Called on the loop thread only.
  void set_wake_handler(std::function<void()> handler) { wake_ = std::move(handler); }

 protected:
  // The core's transmit queue or next_deadline() changed outside on_telegram()/on_time():
  // tells the link. Cheap and safe to call more than once (the link coalesces).
  void wake() const {
    if (wake_) wake_();
  }
  [[nodiscard]] bool send_time_honoured() const { return send_time_honoured_; }

 private:
  std::function<void()> wake_;
  bool send_time_honoured_ = false;
};

}  // namespace rs4sim::dp
