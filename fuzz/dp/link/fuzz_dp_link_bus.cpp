// fuzz_dp_link_bus: arbitrary frames on the in-memory bus into a generic slave.
//
// Input = records [ctl][len][len bytes]: the bytes go onto the wire to slave 5 (through
// its fdl::Decoder, then dp::slave::Slave and the GenericDevice); ctl bit 7 lets 150 ms of
// simulated time pass afterwards (watchdog, poll timeouts), bits 0..6 a few µs. Whatever
// arrives, the bus must neither crash nor stall, and every reply must re-encode. The rest
// of the input also goes through parse_baud_rate (the CLI/serial rate parser).
#include "dp/devices/generic_slave.h"
#include "dp/link/memory_bus.h"
#include "dp/time/baud_rate.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

using namespace rs4sim;

class Sink final : public dp::Station {
 public:
  [[nodiscard]] std::uint8_t address() const override { return 2; }
  void on_telegram(const dp::fdl::Telegram& t, dp::TimePoint) override {
    std::vector<std::uint8_t> bytes;
    dp::fdl::encode(t, bytes);  // every decoded telegram must be encodable again
    if (bytes.empty()) std::abort();
  }
  void on_time(dp::TimePoint) override {}
  [[nodiscard]] std::optional<dp::TimePoint> next_deadline() const override { return std::nullopt; }
  std::optional<dp::fdl::Telegram> take_transmit() override { return std::nullopt; }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)dp::parse_baud_rate(
      std::string_view(reinterpret_cast<const char*>(data), std::min<std::size_t>(size, 24)));
  dp::ManualClock clock;
  dp::link::MemoryBus bus(clock);
  Sink master;
  dp::devices::GenericSlave slave({5, 0x1234, {0x10, 0x20}, true});
  bus.attach(master);
  bus.attach(slave);
  bus.start();
  std::size_t i = 0;
  while (i + 2 <= size) {
    const std::uint8_t ctl = data[i];
    const std::size_t len = std::min<std::size_t>(data[i + 1], size - i - 2);
    bus.send_raw(5, std::span<const std::uint8_t>(data + i + 2, len));
    i += 2 + len;
    bus.run_for((ctl & 0x80) ? std::chrono::milliseconds(150)
                             : std::chrono::microseconds(ctl & 0x7F));
  }
  bus.run_for(std::chrono::seconds(1));
  return 0;
}
