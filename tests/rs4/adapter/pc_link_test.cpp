// PcLink: every transition of the PC adapter's link as a table ([RS4 manual §5.1.1] bit 3,
// [RS4 manual §6.5, §7.1, §7.2]); the table is walked from each listed state, and the events a
// state ignores are listed as self-transitions (pinned as not allowed to move it).
#include "rs4/adapter/pc_link.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace rs4sim::rs4::adapter {
namespace {

using S = PcLink::State;

enum class Event { kAttachIdle, kAttachDuringSync, kDetach, kSyncEnded, kLastAnswerRead, kStart };

struct Row {
  S from;
  Event event;
  S to;
};

// Drives a link into `s` through its public events only.
PcLink in_state(S s) {
  PcLink l;
  switch (s) {
    case S::kDetached: break;
    case S::kAttachedHeld: l.attach(true); break;
    case S::kPendingThrough:
      l.attach(true);
      l.sync_ended();
      break;
    case S::kSwitchedThrough: l.attach(false); break;
  }
  return l;
}

void apply(PcLink& l, Event e) {
  switch (e) {
    case Event::kAttachIdle: l.attach(false); break;
    case Event::kAttachDuringSync: l.attach(true); break;
    case Event::kDetach: l.detach(); break;
    case Event::kSyncEnded: l.sync_ended(); break;
    case Event::kLastAnswerRead: l.last_answer_read(); break;
    case Event::kStart: l.adapter_start(); break;
  }
}

constexpr std::array kTable{
    // detached
    Row{S::kDetached, Event::kAttachIdle, S::kSwitchedThrough},
    Row{S::kDetached, Event::kAttachDuringSync, S::kAttachedHeld},
    Row{S::kDetached, Event::kDetach, S::kDetached},
    Row{S::kDetached, Event::kSyncEnded, S::kDetached},       // not allowed: no adapter
    Row{S::kDetached, Event::kLastAnswerRead, S::kDetached},  // not allowed: no adapter
    Row{S::kDetached, Event::kStart, S::kDetached},
    // attached during a sync: held
    Row{S::kAttachedHeld, Event::kAttachIdle, S::kSwitchedThrough},
    Row{S::kAttachedHeld, Event::kAttachDuringSync, S::kAttachedHeld},
    Row{S::kAttachedHeld, Event::kDetach, S::kDetached},
    Row{S::kAttachedHeld, Event::kSyncEnded, S::kPendingThrough},
    // not allowed: the last answer of a sync still running does not switch through
    Row{S::kAttachedHeld, Event::kLastAnswerRead, S::kAttachedHeld},
    Row{S::kAttachedHeld, Event::kStart, S::kSwitchedThrough},
    // the sync ended, its last answer not yet read
    Row{S::kPendingThrough, Event::kAttachIdle, S::kSwitchedThrough},
    Row{S::kPendingThrough, Event::kAttachDuringSync, S::kPendingThrough},
    Row{S::kPendingThrough, Event::kDetach, S::kDetached},
    Row{S::kPendingThrough, Event::kSyncEnded, S::kPendingThrough},
    Row{S::kPendingThrough, Event::kLastAnswerRead, S::kSwitchedThrough},
    Row{S::kPendingThrough, Event::kStart, S::kSwitchedThrough},
    // switched through: only the removal (or nothing) leaves it
    Row{S::kSwitchedThrough, Event::kAttachIdle, S::kSwitchedThrough},
    Row{S::kSwitchedThrough, Event::kAttachDuringSync, S::kSwitchedThrough},
    Row{S::kSwitchedThrough, Event::kDetach, S::kDetached},
    Row{S::kSwitchedThrough, Event::kSyncEnded, S::kSwitchedThrough},
    Row{S::kSwitchedThrough, Event::kLastAnswerRead, S::kSwitchedThrough},
    Row{S::kSwitchedThrough, Event::kStart, S::kSwitchedThrough},
};

TEST(PcLink, TransitionTable) {
  for (const auto& r : kTable) {
    PcLink l = in_state(r.from);
    ASSERT_EQ(l.state(), r.from) << to_string(r.from);
    apply(l, r.event);
    EXPECT_EQ(l.state(), r.to) << to_string(r.from) << " event " << static_cast<int>(r.event)
                               << " gave " << to_string(l.state());
  }
  // Every (state, event) pair is listed once.
  EXPECT_EQ(kTable.size(), 4U * 6U);
}

TEST(PcLink, ObservationPerState) {
  // attached / switched through (input bit 3, flow state 010) / pending
  struct Obs {
    S s;
    bool attached, through, pending;
  };
  for (const auto& o :
       {Obs{S::kDetached, false, false, false}, Obs{S::kAttachedHeld, true, false, false},
        Obs{S::kPendingThrough, true, false, true}, Obs{S::kSwitchedThrough, true, true, false}}) {
    const PcLink l = in_state(o.s);
    EXPECT_EQ(l.attached(), o.attached) << to_string(o.s);
    EXPECT_EQ(l.switched_through(), o.through) << to_string(o.s);
    EXPECT_EQ(l.pending(), o.pending) << to_string(o.s);
  }
  EXPECT_EQ(std::string(to_string(S::kPendingThrough)), "pending-through");
}

}  // namespace
}  // namespace rs4sim::rs4::adapter
