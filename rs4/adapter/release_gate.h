// The adapter's release gate for the OSSD bit ([RS4 manual §5.1.1] bits 2 and 7,
// [RS4 manual §7.1, §7.2]): whether the RS4 is up since power-on, Proxy-Request, Proxy-Enable as
// read from the first process output, the release (the parameter check passed or is not
// needed) and the background verify still open after a release. Adapter::ossd_release_allowed
// is the one predicate over it (with the adapter's other conditions).
#pragma once

#include <cstdint>

namespace rs4sim::rs4::adapter {

class ReleaseGate {
 public:
  struct Flags {
    bool rs4_up = false;              // the RS4 reached operation since power-on
    bool proxy_request = false;       // input bit 2
    bool proxy_enable = false;        // output bit, as evaluated
    bool proxy_enable_known = false;  // evaluated since DP start-up / PC adapter removal
    bool released = false;            // parameter check passed or not needed
    bool check_open = false;          // released by a sync: its background verify may still fail it
    friend bool operator==(const Flags&, const Flags&) = default;
  };

  constexpr ReleaseGate() = default;
  constexpr explicit ReleaseGate(Flags f) : f_(f) {}

  // ---- events -----------------------------------------------------------------------------
  // Power on or off: the RS4 is down, nothing requested, released or to be checked.
  constexpr void power_change() noexcept {
    f_.rs4_up = f_.released = f_.proxy_request = f_.check_open = false;
  }
  // The adapter (re)starts (power-on, PROFI_CMD_RESET): Proxy-Enable is read again; with a PC
  // adapter attached and the RS4 up the OSSD follows the RS4, else the release waits.
  constexpr void adapter_start(bool pc_attached) noexcept {
    f_.proxy_enable = f_.proxy_enable_known = f_.check_open = false;
    f_.released = f_.rs4_up && pc_attached;
  }
  // The RS4 became operational (≈30 s after power-on [RS4 manual §7.1.1]). Returns whether a
  // Proxy-Request (power-up) is due: not with a PC adapter attached, whose OSSD follows the RS4.
  constexpr bool rs4_operational(bool pc_attached) noexcept {
    if (f_.rs4_up) return false;
    f_.rs4_up = true;
    if (pc_attached) {
      f_.released = true;
      return false;
    }
    f_.proxy_request = true;
    if (f_.proxy_enable_known && !f_.proxy_enable) f_.released = true;
    return true;
  }
  // Data exchange begins or the PC adapter was removed: Proxy-Enable is read again.
  constexpr void forget_proxy_enable() noexcept { f_.proxy_enable_known = false; }
  // A process output: the first one after forget_proxy_enable() sets Proxy-Enable; 0 releases
  // without the proxy ([RS4 manual §5.1.2, §7.1, §7.2]).
  constexpr void process_output(bool proxy_enable, bool sync_running) noexcept {
    if (f_.proxy_enable_known) return;
    f_.proxy_enable_known = true;
    f_.proxy_enable = proxy_enable;
    if (!proxy_enable && f_.rs4_up && !sync_running) f_.released = true;
  }
  // Input bit 2 = 1.
  constexpr void request() noexcept { f_.proxy_request = true; }
  // The PC adapter is attached: "Das Proxy-Request-Bit wird nicht gesetzt solange der PC-Adapter
  // angeschlossen bleibt" [RS4 manual §7.1.2]; its removal requests a sync again.
  constexpr void withdraw_request() noexcept { f_.proxy_request = false; }
  // PROFI_CMD_PROXY_BEGIN: false (nothing starts) without a Proxy-Request; else bit 2 is reset
  // ("wird zurückgesetzt, wenn die Parameterkontrolle beginnt" [RS4 manual §5.1.1]).
  constexpr bool sync_start() noexcept {
    if (!f_.proxy_request) return false;
    f_.proxy_request = f_.check_open = false;
    return true;
  }
  // The sync succeeded: released; "Die Parameter werden im Hintergrund verifiziert"
  // [RS4 manual §7.1.1].
  constexpr void sync_succeeded() noexcept { f_.released = f_.check_open = true; }
  // A sync failed, or the set changed during one: with Proxy-Enable 1 the release is withdrawn.
  constexpr void set_in_doubt() noexcept {
    if (f_.proxy_enable) f_.released = false;
  }
  // The background verify after a release failed: its report is taken once.
  constexpr void verify_failed() noexcept { f_.check_open = false; }

  // ---- observation -------------------------------------------------------------------------
  [[nodiscard]] constexpr const Flags& flags() const noexcept { return f_; }
  [[nodiscard]] constexpr bool rs4_up() const noexcept { return f_.rs4_up; }
  [[nodiscard]] constexpr bool proxy_request() const noexcept { return f_.proxy_request; }
  [[nodiscard]] constexpr bool proxy_enable() const noexcept { return f_.proxy_enable; }
  [[nodiscard]] constexpr bool released() const noexcept { return f_.released; }
  [[nodiscard]] constexpr bool check_open() const noexcept { return f_.check_open; }
  // The gate's share of the OSSD bit and of bit 6 (not operational).
  [[nodiscard]] constexpr bool open() const noexcept { return f_.rs4_up && f_.released; }

 private:
  Flags f_;
};

}  // namespace rs4sim::rs4::adapter
