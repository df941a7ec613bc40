#pragma once
// What the Receiver does with one slave-mode message [METRON manual "Slave line mode"]:
// the checks in the order parity → (node mode: address) → E1 → E2 → E3/E5 → E4, then the
// command (DECISION on the order: [docs/metron.md#error-order]). In node mode a message to
// address 255 (broadcast) never gets a reply: commands #1..#7 are executed, #8..#13 are
// ignored, and a message failing any check is dropped [METRON manual "With node"].

#include "metron/options.h"
#include "metron/scene.h"
#include "metron/slave_receiver.h"
#include "metron/slave_state.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace rs4sim::metron {

// How a message ended, for the counters.
enum class Disposition : std::uint8_t {
  kExecuted,         // the command ran (a reply follows unless broadcast or Reset)
  kErrorAnswer,      // refused with E1..E5 (answered unless broadcast)
  kParityRejected,   // no reply
  kNotForUs,         // node mode, another address: ignored
  kBroadcastIgnored  // #8..#13 to address 255, or a broadcast failing a check
};

struct Reaction {
  Disposition disposition = Disposition::kExecuted;
  std::optional<Command> command;
  std::optional<ErrorCase> error;
  // The reply code and data, when a reply goes out.
  std::optional<std::uint8_t> reply_code;
  std::vector<std::uint8_t> reply_data;
  bool reset = false;  // Reset software was executed
};

[[nodiscard]] Reaction handle(const SlaveMessage& m, const Options& options, const Scene& scene,
                              SlaveState& state);

}  // namespace rs4sim::metron
