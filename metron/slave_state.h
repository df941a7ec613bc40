#pragma once
// The Receiver state the slave commands change: the OSSD functions (enabled, disabled, in
// stand-by; a Start/Stop OSSD measurement running) and the Start/Stop measurement on one
// field with the maximum seen so far [METRON manual "Slave line mode"].

#include "metron/scene.h"
#include "metron/wire_table.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace rs4sim::metron {

enum class OssdFunction : std::uint8_t { kEnabled, kDisabled, kStandby };

// "enabled", "disabled", "standby" (the API's word).
[[nodiscard]] constexpr std::string_view to_token(OssdFunction f) noexcept {
  switch (f) {
    case OssdFunction::kEnabled: return "enabled";
    case OssdFunction::kDisabled: return "disabled";
    case OssdFunction::kStandby: return "standby";
  }
  return "?";
}

struct SlaveState {
  OssdFunction ossd = OssdFunction::kEnabled;
  bool ossd_measuring = false;
  std::optional<Measurement> measuring;
  std::uint8_t maximum = 0;

  // A scene change while a Start/Stop measurement runs: keep the maximum.
  void track(const Scene& scene) {
    if (measuring && scene.measure(*measuring) > maximum) maximum = scene.measure(*measuring);
  }
};

// Both OSSDs are ON only with the functions enabled, the curtain synchronised and no beam
// interrupted; every other path leaves them OFF. The OSSD logic itself is in handbook
// 8540639; this is the project's model (DECISION, [docs/metron.md#ossd]).
[[nodiscard]] inline bool ossd_on(const SlaveState& s, const Scene& scene) {
  return s.ossd == OssdFunction::kEnabled && scene.synchronised() && !scene.any_interrupted();
}

}  // namespace rs4sim::metron
