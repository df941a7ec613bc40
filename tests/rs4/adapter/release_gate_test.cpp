// ReleaseGate: each transition of the adapter's release gate as a table row
// ([RS4 manual §5.1.1] bits 2, 6, 7, [RS4 manual §7.1, §7.2]). A state is written as letters:
// U RS4 up, R Proxy-Request, E Proxy-Enable, K Proxy-Enable known, L released, C background
// verify open; "-" none. Rows whose state does not change pin a transition that is not allowed.
#include "rs4/adapter/release_gate.h"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace rs4sim::rs4::adapter {
namespace {

using Flags = ReleaseGate::Flags;

Flags f(std::string_view s) {
  Flags x;
  for (const char c : s) {
    switch (c) {
      case 'U': x.rs4_up = true; break;
      case 'R': x.proxy_request = true; break;
      case 'E': x.proxy_enable = true; break;
      case 'K': x.proxy_enable_known = true; break;
      case 'L': x.released = true; break;
      case 'C': x.check_open = true; break;
      default: break;
    }
  }
  return x;
}

std::string letters(const Flags& x) {
  std::string s;
  if (x.rs4_up) s += 'U';
  if (x.proxy_request) s += 'R';
  if (x.proxy_enable) s += 'E';
  if (x.proxy_enable_known) s += 'K';
  if (x.released) s += 'L';
  if (x.check_open) s += 'C';
  return s.empty() ? "-" : s;
}

enum class Event {
  kPowerChange,
  kStartPcAttached,
  kStartNoPc,
  kRs4UpPcAttached,
  kRs4UpNoPc,
  kForgetEnable,
  kOutputEnable1,
  kOutputEnable0,
  kOutputEnable0DuringSync,
  kRequest,
  kSyncStart,
  kSyncSucceeded,
  kSetInDoubt,
  kVerifyFailed,
};

struct Row {
  std::string_view from;
  Event event;
  std::string_view to;
  bool result = false;  // rs4_operational(): Proxy-Request due; sync_start(): started
};

bool apply(ReleaseGate& g, Event e) {
  switch (e) {
    case Event::kPowerChange: g.power_change(); return false;
    case Event::kStartPcAttached: g.adapter_start(true); return false;
    case Event::kStartNoPc: g.adapter_start(false); return false;
    case Event::kRs4UpPcAttached: return g.rs4_operational(true);
    case Event::kRs4UpNoPc: return g.rs4_operational(false);
    case Event::kForgetEnable: g.forget_proxy_enable(); return false;
    case Event::kOutputEnable1: g.process_output(true, false); return false;
    case Event::kOutputEnable0: g.process_output(false, false); return false;
    case Event::kOutputEnable0DuringSync: g.process_output(false, true); return false;
    case Event::kRequest: g.request(); return false;
    case Event::kSyncStart: return g.sync_start();
    case Event::kSyncSucceeded: g.sync_succeeded(); return false;
    case Event::kSetInDoubt: g.set_in_doubt(); return false;
    case Event::kVerifyFailed: g.verify_failed(); return false;
  }
  return false;
}

const std::vector<Row>& table() {
  static const std::vector<Row> rows{
      // power on/off: everything but Proxy-Enable cleared
      {"URKLC", Event::kPowerChange, "K"},
      {"UEKL", Event::kPowerChange, "EK"},
      // adapter start: Proxy-Enable read again; released only with the RS4 up and a PC adapter
      {"UREKLC", Event::kStartNoPc, "UR"},
      {"UEK", Event::kStartPcAttached, "UL"},
      {"EK", Event::kStartPcAttached, "-"},  // not allowed: released while the RS4 is down
      // the RS4 becomes operational
      {"-", Event::kRs4UpNoPc, "UR", true},
      {"K", Event::kRs4UpNoPc, "URKL", true},       // Proxy-Enable 0 known: released at once
      {"EK", Event::kRs4UpNoPc, "UREK", true},      // Proxy-Enable 1: waits for the sync
      {"-", Event::kRs4UpPcAttached, "UL", false},  // PC adapter: no request, OSSD follows
      {"UR", Event::kRs4UpNoPc, "UR", false},       // not allowed: a second power-up request
      // Proxy-Enable from the first process output
      {"UR", Event::kOutputEnable1, "UREK"},
      {"UR", Event::kOutputEnable0, "URKL"},
      {"R", Event::kOutputEnable0, "RK"},              // not allowed: released while RS4 down
      {"UR", Event::kOutputEnable0DuringSync, "URK"},  // not allowed: released during a sync
      {"UREK", Event::kOutputEnable0, "UREK"},         // not allowed: read once only
      {"UEKL", Event::kForgetEnable, "UEL"},
      {"UEL", Event::kOutputEnable0, "UKL"},
      // the sync
      {"U", Event::kRequest, "UR"},
      {"UREK", Event::kSyncStart, "UEK", true},
      {"UEKLC", Event::kSyncStart, "UEKLC", false},  // not allowed: no Proxy-Request
      {"UREKLC", Event::kSyncStart, "UEKL", true},   // a new sync closes the background verify
      {"UEK", Event::kSyncSucceeded, "UEKLC"},
      {"UEKLC", Event::kSetInDoubt, "UEKC"},  // Proxy-Enable 1: the release is withdrawn
      {"UKLC", Event::kSetInDoubt, "UKLC"},   // not allowed with Proxy-Enable 0
      {"UEKLC", Event::kVerifyFailed, "UEKL"},
  };
  return rows;
}

TEST(ReleaseGate, TransitionTable) {
  for (const auto& r : table()) {
    ReleaseGate g{f(r.from)};
    const bool result = apply(g, r.event);
    EXPECT_EQ(letters(g.flags()), letters(f(r.to)))
        << r.from << " event " << static_cast<int>(r.event);
    EXPECT_EQ(result, r.result) << r.from << " event " << static_cast<int>(r.event);
  }
}

// The gate's share of the OSSD bit: the RS4 up and released, nothing else.
TEST(ReleaseGate, OpenOnlyWithTheRs4UpAndReleased) {
  EXPECT_TRUE(ReleaseGate{f("UL")}.open());
  EXPECT_TRUE(ReleaseGate{f("UREKLC")}.open());
  EXPECT_FALSE(ReleaseGate{f("L")}.open());
  EXPECT_FALSE(ReleaseGate{f("UREKC")}.open());
  EXPECT_FALSE(ReleaseGate{}.open());
}

// The start-up of [RS4 manual §7.1.1] end to end: power-on, Proxy-Enable 1, the RS4 up, the
// sync, the release; a PC adapter removal then reads Proxy-Enable again.
TEST(ReleaseGate, StartUpWithTheProxy) {
  ReleaseGate g;
  g.power_change();
  g.adapter_start(false);
  g.process_output(true, false);
  EXPECT_FALSE(g.open());
  EXPECT_TRUE(g.rs4_operational(false));
  EXPECT_TRUE(g.proxy_request());
  EXPECT_FALSE(g.open());
  EXPECT_TRUE(g.sync_start());
  EXPECT_FALSE(g.proxy_request());
  g.sync_succeeded();
  EXPECT_TRUE(g.open());
  EXPECT_TRUE(g.check_open());
  g.forget_proxy_enable();
  g.process_output(false, false);
  EXPECT_FALSE(g.proxy_enable());
  EXPECT_TRUE(g.open());
}

}  // namespace
}  // namespace rs4sim::rs4::adapter
