// ProxyDriver: scheduler ↔ RecordChannel.
#include "proxy/proxy_driver.h"

#include <variant>

namespace rs4sim::proxy {

void ProxyDriver::on_input_byte(std::uint8_t address, std::uint8_t byte) {
  if (auto* sync = scheduler_.find(address)) sync->set_input_byte(byte);
}

void ProxyDriver::set_proxy_enable(std::uint8_t address, bool enabled) {
  if (auto* sync = scheduler_.find(address)) sync->set_proxy_enable(enabled);
}

void ProxyDriver::on_record_result(std::uint8_t address, const RecordResult& result,
                                   dp::TimePoint now) {
  auto* sync = scheduler_.find(address);
  if (sync == nullptr) return;
  sync->on_record_result(result, now);
  pump(address, *sync, now);
}

void ProxyDriver::poll(dp::TimePoint now) {
  scheduler_.poll(now);
  for (const auto address : scheduler_.addresses()) pump(address, *scheduler_.find(address), now);
  scheduler_.poll(now);  // a sync that ended frees its slot at once
}

void ProxyDriver::pump(std::uint8_t address, ProxySync& sync, dp::TimePoint now) {
  auto request = sync.take_request(now);
  // The retentive record is saved before the record goes out: a restart after a 98 WRITE
  // finds the sync open (docs/proxy.md "Retentive record").
  (void)scheduler_.persist(address, now);
  if (!request) return;
  if (const auto* write = std::get_if<RecordWrite>(&*request)) {
    channel_.submit_write(address, write->data);
  } else {
    channel_.submit_read(address, std::get<RecordRead>(*request).length);
  }
}

}  // namespace rs4sim::proxy
