// The link between the optical PC adapter and the RS4's RS232 as the PROFIsafe adapter sees
// it ([RS4 manual §5.1.1] input bit 3 "RS232 aktiv", [RS4 manual §6.5, §7.1, §7.2]): attached
// (reed contact), switched through (the RS232 belongs to the PC; no PROFIBUS communication with
// the RS4, flow state 010), or switched through once the running sync's last answer was read.
#pragma once

#include <cstdint>

namespace rs4sim::rs4::adapter {

class PcLink {
 public:
  enum class State : std::uint8_t {
    kDetached,        // no PC adapter
    kAttachedHeld,    // attached during a sync: not yet switched through
    kPendingThrough,  // the sync ended: switched through once its last answer was read
    kSwitchedThrough,
  };

  // ---- events -----------------------------------------------------------------------------
  // Reed contact closes. During a sync the RS232 is switched through only after it.
  constexpr void attach(bool sync_running) noexcept {
    if (state_ == State::kSwitchedThrough) return;
    if (!sync_running) {
      state_ = State::kSwitchedThrough;
    } else if (state_ == State::kDetached) {
      state_ = State::kAttachedHeld;
    }
  }
  // Reed contact opens.
  constexpr void detach() noexcept { state_ = State::kDetached; }
  // The sync ended (success or failure).
  constexpr void sync_ended() noexcept {
    if (state_ == State::kAttachedHeld) state_ = State::kPendingThrough;
  }
  // The proxy has read the sync's last answer.
  constexpr void last_answer_read() noexcept {
    if (state_ == State::kPendingThrough) state_ = State::kSwitchedThrough;
  }
  // The adapter (re)starts (power-on, PROFI_CMD_RESET): an attached PC adapter is switched
  // through at once (no sync runs after a start).
  constexpr void adapter_start() noexcept {
    if (state_ != State::kDetached) state_ = State::kSwitchedThrough;
  }

  // ---- observation -------------------------------------------------------------------------
  [[nodiscard]] constexpr State state() const noexcept { return state_; }
  [[nodiscard]] constexpr bool attached() const noexcept { return state_ != State::kDetached; }
  // Input bit 3, flow state 010.
  [[nodiscard]] constexpr bool switched_through() const noexcept {
    return state_ == State::kSwitchedThrough;
  }
  [[nodiscard]] constexpr bool pending() const noexcept { return state_ == State::kPendingThrough; }

 private:
  State state_ = State::kDetached;
};

[[nodiscard]] const char* to_string(PcLink::State s) noexcept;

}  // namespace rs4sim::rs4::adapter
