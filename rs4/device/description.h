#pragma once
// The RS4/PROFIsafe described once (stream/device_description.h): its kind, link, address
// rule, the options of `rs4sim run --device rs4` and their checks, and its faults (the
// scanner's, rs4/scanner/faults.h) as the API's DeviceState.faults_present names them. The
// RS4's API has no counters message: its description lists none.

#include "rs4/device/rs4_device.h"
#include "stream/device_description.h"

#include <optional>
#include <string>
#include <vector>

namespace rs4sim::rs4::device {

using Description = stream::DeviceDescription<Rs4Device, stream::NoCounters>;

[[nodiscard]] const Description& description();

inline constexpr int kDefaultAddress = 4;  // factory setting of the switches [RS4 manual §2]
inline constexpr int kDefaultBootTimeMs = 30000;  // boot until operational [RS4 manual §1]
inline constexpr int kMaxBootTimeMs = 600000;
// One scan [docs/decisions.md#rs4-command-time]; 2 minutes at most [RS4 manual §5.2.1].
inline constexpr int kDefaultCommandTimeMs = 40;
inline constexpr int kMaxCommandTimeMs = 120000;
// "Reaktionszeit PROFIsafe-Adapter 10 ms" [RS4 manual, technical data].
inline constexpr int kDefaultResponseTimeMs = 10;
inline constexpr int kMaxResponseTimeMs = 1000;

// What `rs4sim run --device rs4` sets (unset: empty/nullopt); check_run_options() fills the
// defaults. The app parses the flags into it; the files (--state, --gsd) it opens itself.
struct RunOptions {
  std::vector<int> addresses;  // --address in the order given; empty: kDefaultAddress
  std::vector<long long> serial_numbers;
  std::vector<std::string> state_files;
  std::optional<int> boot_time_ms;
  std::optional<int> command_time_ms;
  std::optional<int> response_time_ms;
  bool rs232 = false;   // --rs232 given
  bool gsd = false;     // --gsd given
  bool module = false;  // --module given
};

// Fills the defaults and checks the options; empty when usable, else one sentence naming
// the option and what is allowed ("--address: 126 is outside 0..125 ...").
[[nodiscard]] std::string check_run_options(RunOptions& o);

}  // namespace rs4sim::rs4::device
