// libFuzzer target: the F-device driver fed with arbitrary host PDUs and time steps.
// Input: a 10-byte F-parameter block, then records of [time step ms, length, bytes...].
// Invariants: never crash; the response is always 5 bytes; real input data leave the device
// only when sends_process_values() (the one predicate) is true.
#include "profisafe/f_device.h"

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rs4sim::profisafe;
  if (size < kFParametersSize) return 0;
  FDevice dev(FDeviceConfig{DeviceProfile{}, 1, {}});
  (void)dev.set_parameters(std::span<const std::uint8_t>(data, kFParametersSize));
  const std::uint8_t input = 0xA5;
  dev.set_input(std::span<const std::uint8_t>(&input, 1));
  TimePoint now{std::chrono::hours(1)};
  std::size_t at = kFParametersSize;
  while (at + 2 <= size) {
    now += std::chrono::milliseconds(data[at]);
    const std::size_t len = std::min<std::size_t>(data[at + 1] % 8u, size - at - 2);
    (void)dev.on_pdu(std::span<const std::uint8_t>(data + at + 2, len), now);
    at += 2 + len;
    const auto r = dev.response();
    if (r.size() != 5) std::abort();
    if (r[0] == input && !dev.sends_process_values()) std::abort();
    if (dev.sends_process_values() && dev.state() != FDeviceState::kRun) std::abort();
  }
  return 0;
}
