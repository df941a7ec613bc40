#pragma once
// Frame count bit (FCB/FCV) rules, [IEC 61158-4-3 FCB/FCV].
//
// FcbResponder (slave side): classifies each request from an initiator as first / new /
// repeat and keeps the last reply, so a repeated request gets the stored reply again
// instead of a second execution. FcbInitiator (master side): one FCB state per responder.

#include "dp/fdl/telegram.h"

#include <array>
#include <cstdint>
#include <optional>

namespace rs4sim::dp::fdl {

enum class FcbVerdict : std::uint8_t {
  kNotEvaluated,  // FCV=0, FCB=0 (FDL_Status, SDN broadcast): execute, state unchanged
  kFirst,         // FCV=0, FCB=1: first message cycle from this SA; execute
  kNew,           // FCV=1 with toggled FCB, or from a different SA: execute
  kRepeat,        // FCV=1, same SA, same FCB: do not execute; resend stored_reply()
};

class FcbResponder {
 public:
  // Classifies request `fc` from initiator `sa` and updates the state. After kFirst/kNew
  // the stored reply is cleared until store_reply() is called for the new request.
  FcbVerdict on_request(std::uint8_t sa, FrameControl fc);

  // Keeps the reply sent for the last kFirst/kNew request (SC or a full telegram).
  void store_reply(const Telegram& reply);

  // The reply to resend for a kRepeat; nullptr if none was stored (e.g. the repeated
  // request got no reply) — the caller then treats the request as new.
  [[nodiscard]] const Telegram* stored_reply() const { return has_reply_ ? &reply_ : nullptr; }

  // Forget the initiator (slave reset / power on).
  void reset();

  [[nodiscard]] std::optional<std::uint8_t> initiator() const { return sa_; }

 private:
  std::optional<std::uint8_t> sa_;
  bool fcb_ = false;
  bool has_reply_ = false;
  Telegram reply_;
};

class FcbInitiator {
 public:
  // FC for a new action frame to `da` with function `f`: the first frame after start or
  // after responder_lost() has FCV=0, FCB=1; every later one FCV=1 with FCB toggled.
  FrameControl next(std::uint8_t da, RequestFunction f);

  // FC for re-sending the last frame to `da` (missing/garbled reply): same FCB/FCV.
  // Precondition: next() was called for `da` before; otherwise equals a first frame.
  [[nodiscard]] FrameControl repeat(std::uint8_t da, RequestFunction f) const;

  // True if the last frame to `da` was a first frame (FCV=0), which is not retried
  // ([IEC 61158-4-3 FCB/FCV]).
  [[nodiscard]] bool last_was_first(std::uint8_t da) const;

  // The responder was marked non-operational: the next frame is a first frame again.
  void responder_lost(std::uint8_t da);
  void reset_all();

  // FC without FCB semantics (FDL_Status, SDN broadcasts): FCV=0, FCB=0.
  static constexpr FrameControl unsequenced(RequestFunction f) {
    return FrameControl::request(f, false, false);
  }

 private:
  enum class State : std::uint8_t { kFresh, kFirstSent, kSequenced };
  struct Entry {
    State state = State::kFresh;
    bool fcb = false;  // FCB of the last frame sent
  };
  std::array<Entry, 128> entries_{};
};

}  // namespace rs4sim::dp::fdl
