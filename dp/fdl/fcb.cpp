// FCB/FCV rules, [IEC 61158-4-3 FCB/FCV].
#include "dp/fdl/fcb.h"

#include "dp/fdl/telegram_copy.h"

namespace rs4sim::dp::fdl {

FcbVerdict FcbResponder::on_request(std::uint8_t sa, FrameControl fc) {
  if (!fc.fcv()) {
    if (!fc.fcb()) return FcbVerdict::kNotEvaluated;  // FDL_Status, SDN: no FCB semantics
    // First message cycle: remember FCB=1 with the initiator's SA.
    sa_ = sa;
    fcb_ = true;
    has_reply_ = false;
    return FcbVerdict::kFirst;
  }
  if (sa_ != sa) {
    // A different initiator: no evaluation, take over its SA and FCB.
    sa_ = sa;
    fcb_ = fc.fcb();
    has_reply_ = false;
    return FcbVerdict::kNew;
  }
  if (fc.fcb() == fcb_) return FcbVerdict::kRepeat;
  fcb_ = fc.fcb();
  has_reply_ = false;
  return FcbVerdict::kNew;
}

void FcbResponder::store_reply(const Telegram& reply) {
  copy_telegram(reply_, reply);  // a reply's DU is a few bytes
  has_reply_ = true;
}

void FcbResponder::reset() {
  sa_.reset();
  fcb_ = false;
  has_reply_ = false;
}

FrameControl FcbInitiator::next(std::uint8_t da, RequestFunction f) {
  Entry& e = entries_[da & 0x7FU];
  if (e.state == State::kFresh) {
    e.state = State::kFirstSent;
    e.fcb = true;
    return FrameControl::request(f, true, false);
  }
  e.state = State::kSequenced;
  e.fcb = !e.fcb;
  return FrameControl::request(f, e.fcb, true);
}

FrameControl FcbInitiator::repeat(std::uint8_t da, RequestFunction f) const {
  const Entry& e = entries_[da & 0x7FU];
  switch (e.state) {
    case State::kFresh:
    case State::kFirstSent: return FrameControl::request(f, true, false);
    case State::kSequenced: return FrameControl::request(f, e.fcb, true);
  }
  return FrameControl::request(f, true, false);
}

bool FcbInitiator::last_was_first(std::uint8_t da) const {
  return entries_[da & 0x7FU].state == State::kFirstSent;
}

void FcbInitiator::responder_lost(std::uint8_t da) { entries_[da & 0x7FU] = Entry{}; }

void FcbInitiator::reset_all() { entries_.fill(Entry{}); }

}  // namespace rs4sim::dp::fdl
