#include "rs4/adapter/pc_link.h"

namespace rs4sim::rs4::adapter {

const char* to_string(PcLink::State s) noexcept {
  switch (s) {
    case PcLink::State::kDetached: return "detached";
    case PcLink::State::kAttachedHeld: return "attached-held";
    case PcLink::State::kPendingThrough: return "pending-through";
    case PcLink::State::kSwitchedThrough: return "switched-through";
  }
  return "?";
}

}  // namespace rs4sim::rs4::adapter
