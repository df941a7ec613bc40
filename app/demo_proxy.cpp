#include "app/demo_proxy.h"

#include "app/master_proxy.h"

#include <chrono>

namespace rs4sim::app {
namespace {

proxy::ProxySyncConfig config(const rs4::device::Rs4Segment& segment) {
  proxy::ProxySyncConfig c;
  c.station = DemoProxy::station();
  c.station.address = segment.rs4_address();
  // Archive timestamps: the wall clock at the demo's simulated instant 0.
  const auto wall =
      std::chrono::time_point_cast<std::chrono::milliseconds>(std::chrono::system_clock::now());
  c.wall_at_zero = storage::Timestamp{
      wall.time_since_epoch() -
      std::chrono::duration_cast<std::chrono::milliseconds>(segment.now().time_since_epoch())};
  return c;
}

}  // namespace

DemoProxy::DemoProxy(rs4::device::Rs4Segment& segment, storage::ParameterArchive& archive)
    : segment_(segment), sync_(config(segment), archive) {}

proxy::RecordResult DemoProxy::exchange(const proxy::RecordRequest& request) {
  ++records_;
  const auto* w = std::get_if<proxy::RecordWrite>(&request);
  const auto r = w != nullptr ? segment_.write_record(w->data)
                              : segment_.read_record(std::get<proxy::RecordRead>(request).length);
  return r ? to_record_result(*r) : proxy::RecordResult::no_response();
}

bool DemoProxy::run_sync(dp::Duration timeout) {
  sync_.set_proxy_enable(true);
  sync_.set_input_byte(segment_.input_byte());
  if (!sync_.ready(segment_.now())) return false;
  sync_.start(segment_.now());
  const auto end = segment_.now() + timeout;
  while (segment_.now() < end) {
    sync_.set_input_byte(segment_.input_byte());
    if (!sync_.active()) return true;
    if (auto req = sync_.take_request(segment_.now())) {
      sync_.on_record_result(exchange(*req), segment_.now());
    } else {
      segment_.run_for(std::chrono::milliseconds(10));
      sync_.tick(segment_.now());
    }
  }
  return false;
}

}  // namespace rs4sim::app
