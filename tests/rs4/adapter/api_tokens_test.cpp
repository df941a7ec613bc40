// The words the API and the event stream show for the adapter's LED and proxy phase
// (DeviceState.led, DeviceState.proxy_phase, StateChange "led"/"proxy-phase"; docs/rpc.md).
// Clients compare them (python/, tests/rpc): each one is pinned here as a literal.
#include "rs4/adapter/adapter.h"

#include <gtest/gtest.h>

#include <string_view>
#include <utility>

namespace rs4sim::rs4::adapter {
namespace {

TEST(AdapterTokens, EveryLedStateHasItsApiWord) {
  const std::pair<LedState, std::string_view> expected[] = {
      {LedState::kDark, "dark"},
      {LedState::kSteadyInit, "steady-init"},
      {LedState::kFastBlink, "fast-blink"},
      {LedState::kOffConnected, "off-connected"},
      {LedState::kSteadyFault, "steady-fault"},
      {LedState::kSlowBlink, "slow-blink"},
  };
  for (const auto& [state, token] : expected) EXPECT_EQ(to_token(state), token) << token;
  // The people's wording stays apart from the token.
  EXPECT_STREQ(to_string(LedState::kOffConnected), "off (connected)");
  EXPECT_EQ(to_token(static_cast<LedState>(200)), "?");
}

TEST(AdapterTokens, EveryProxyPhaseHasItsApiWord) {
  const std::pair<ProxyPhase, std::string_view> expected[] = {
      {ProxyPhase::kWaitRs4, "wait-rs4"},
      {ProxyPhase::kRequested, "requested"},
      {ProxyPhase::kSyncRunning, "sync-running"},
      {ProxyPhase::kDone, "done"},
  };
  for (const auto& [phase, token] : expected) EXPECT_EQ(to_token(phase), token) << token;
  EXPECT_STREQ(to_string(ProxyPhase::kWaitRs4), "wait for RS4");
  EXPECT_EQ(to_token(static_cast<ProxyPhase>(200)), "?");
}

}  // namespace
}  // namespace rs4sim::rs4::adapter
