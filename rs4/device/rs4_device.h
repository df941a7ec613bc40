#pragma once
// One emulated RS4/PROFIsafe on a PROFIBUS link ([RS4 manual §2.3, §2.4, §4.5, §5.2.2]):
// a dp::slave::Slave around an rs4::adapter::Adapter (which owns the Scanner), as a dp::Station
// so that every link (memory bus, serial/pty, UDP) runs it.
//
// Device behaviour this class adds on top of the adapter:
// * power: off = the station is silent; power-on reads the hex address switches ([RS4 manual §4.5]:
//   bit 7 masked, 127/255 refused → silent, LED steady fault) and starts a fresh DP
//   slave in Wait_Prm at that address;
// * PROFI_CMD_RESET (0x94, [RS4 manual §5.2.2]): the adapter restarts and the DP link is down for
// ≈2 s:
//   the station stays silent, then comes back as a fresh slave in Wait_Prm.
// The station address is fixed at power-up (like the device); a link keyed by address
// (MemoryBus) must re-attach the station after a power-up at another address.

#include "dp/slave/slave.h"
#include "dp/station.h"
#include "rs4/adapter/adapter.h"

#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>

namespace rs4sim::rs4::device {

using dp::TimePoint;
using std::chrono::milliseconds;

struct Rs4DeviceConfig {
  adapter::AddressSwitches switches{};  // HexH/HexL; factory setting 4 ([RS4 manual §4.5])
  milliseconds boot_time{30000};       // RS4 boot until operational ([RS4 manual §7.1.1]: ≈30 s)
  milliseconds adapter_init{2500};     // adapter LED steady 2–3 s ([RS4 manual §4.4])
  milliseconds reset_link_down{2000};  // PROFI_CMD_RESET: DP link down ≈2 s ([RS4 manual §5.2.2])
  scanner::ScannerConfig scanner{};    // boot_duration is replaced by boot_time
  adapter::AdapterConfig adapter{};    // the rest of the adapter's settings
};

// Switch positions for a station address 0..126 (HexH = high nibble, HexL = low nibble).
[[nodiscard]] constexpr adapter::AddressSwitches switches_for(std::uint8_t address) noexcept {
  return {static_cast<std::uint8_t>((address >> 4) & 0x0F),
          static_cast<std::uint8_t>(address & 0x0F)};
}

// The dp::slave::Slave features of the RS4/PROFIsafe as its GSD declares them (RSIM5234.gsd:
// DPV1, C2, diagnosis/update alarms in sequence mode for 8 alarms, no Sync/Freeze).
[[nodiscard]] dp::slave::Config rs4_slave_config(std::uint8_t address);

struct Rs4DeviceCounters {
  std::uint64_t power_ups = 0;
  std::uint64_t link_drops = 0;            // adapter resets that took the DP link down
  std::uint64_t ignored_while_silent = 0;  // telegrams heard while off / link down / no address
};

class Rs4Device final : public dp::Station {
 public:
  explicit Rs4Device(const Rs4DeviceConfig& config = {});  // powered off
  Rs4Device(const Rs4Device&) = delete;
  Rs4Device& operator=(const Rs4Device&) = delete;

  // ---- power and address switches ([RS4 manual §2.3, §2.4, §4.5]) -------------------------------
  void power_on(TimePoint now);
  void power_off(TimePoint now);
  void power_cycle(TimePoint now);
  [[nodiscard]] bool powered() const noexcept { return powered_; }
  // Takes effect at the next power-up (or adapter reset), as on the device.
  void set_address_switches(adapter::AddressSwitches s) noexcept {
    adapter_.set_address_switches(s);
  }
  [[nodiscard]] adapter::AddressSwitches address_switches() const noexcept {
    return adapter_.address_switches();
  }
  // True while the station answers on the bus (powered, valid address, link not down).
  [[nodiscard]] bool on_bus(TimePoint now) const noexcept;
  [[nodiscard]] bool link_down() const noexcept { return link_down_; }

  // Device exchange: another RS4 unit on this adapter (Adapter::exchange_scanner). Only while
  // powered off; false while powered.
  bool exchange_scanner(const scanner::ScannerConfig& unit) {
    return !powered_ && adapter_.exchange_scanner(unit);
  }
  // The whole device exchange of [RS4 manual §7.1] (scenario 4) at `now`: power off, a new
  // unit with factory settings and `serial_number` (its other settings as this device was
  // configured with), power on. Serial number 0 is refused (false): it is the transfer
  // form's "none".
  bool exchange_unit(std::uint32_t serial_number, TimePoint now);

  // ---- control / observation ------------------------------------------------------------
  adapter::Adapter& adapter() noexcept { return adapter_; }
  [[nodiscard]] const adapter::Adapter& adapter() const noexcept { return adapter_; }
  scanner::Scanner& scanner() noexcept { return adapter_.scanner(); }
  [[nodiscard]] const scanner::Scanner& scanner() const noexcept { return adapter_.scanner(); }
  [[nodiscard]] const dp::slave::Slave& slave() const noexcept { return slave_; }
  [[nodiscard]] const Rs4DeviceCounters& counters() const noexcept { return counters_; }
  // Heap owned by the device beyond sizeof (scene obstacles), for the memory benchmark.
  [[nodiscard]] std::size_t heap_bytes() const noexcept { return adapter_.scanner().heap_bytes(); }

  // ---- dp::Station -------------------------------------------------------------------------
  [[nodiscard]] std::uint8_t address() const override { return slave_.address(); }
  void on_telegram(const dp::fdl::Telegram& t, TimePoint now) override;
  void on_time(TimePoint now) override;
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override;
  std::optional<dp::fdl::Telegram> take_transmit() override;
  void on_malformed_frame(std::error_code why) override;
  [[nodiscard]] std::uint16_t min_tsdr_bits() const override { return slave_.min_tsdr_bits(); }

 private:
  void restart_slave(std::uint8_t address);
  void after_core_call(TimePoint now);

  scanner::ScannerConfig unit_;  // the configured unit, the template of exchange_unit()
  adapter::Adapter adapter_;
  dp::slave::Slave slave_;  // for the device's lifetime: the adapter keeps a SlaveControl&
  std::deque<dp::fdl::Telegram> pending_;  // replies the slave queued just before the link drop
  bool powered_ = false;
  bool link_down_ = false;
  Rs4DeviceCounters counters_;
};

}  // namespace rs4sim::rs4::device
