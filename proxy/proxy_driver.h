#pragma once
// ProxyDriver: the glue between a ProxyScheduler and a class 1 master, without depending on
// dp/master. The owner implements RecordChannel with DPV1 MSAC_C1 WRITE/READ of slot 0,
// index 2 ([RS4 manual §5.2]) and feeds the inputs and the record results back
// (docs/proxy.md "Driver").

#include "proxy/proxy_scheduler.h"

#include <cstdint>
#include <span>

namespace rs4sim::proxy {

class RecordChannel {
 public:
  virtual ~RecordChannel() = default;
  virtual void submit_write(std::uint8_t address, std::span<const std::uint8_t> record) = 0;
  virtual void submit_read(std::uint8_t address, std::uint8_t length) = 0;
};

class ProxyDriver {
 public:
  ProxyDriver(ProxyScheduler& scheduler, RecordChannel& channel)
      : scheduler_(scheduler), channel_(channel) {}

  // The PROFIsafe-unwrapped input byte and Proxy-Enable (output byte bit 6) of a slave.
  void on_input_byte(std::uint8_t address, std::uint8_t byte);
  void set_proxy_enable(std::uint8_t address, bool enabled);
  // The result of the record submitted last for that slave; issues the next one.
  void on_record_result(std::uint8_t address, const RecordResult& result, dp::TimePoint now);
  // Call on every cycle or at next_wakeup(): grants syncs and issues due records.
  void poll(dp::TimePoint now);
  [[nodiscard]] std::optional<dp::TimePoint> next_wakeup() const noexcept {
    return scheduler_.next_wakeup();
  }

 private:
  void pump(std::uint8_t address, ProxySync& sync, dp::TimePoint now);

  ProxyScheduler& scheduler_;
  RecordChannel& channel_;
};

}  // namespace rs4sim::proxy
