#include "app/demos/demo_proxy.h"

#include "app/runtime/master_proxy.h"

namespace rs4sim::app {
namespace {

proxy::ProxySyncConfig config(const rs4::device::Rs4Segment& segment) {
  proxy::ProxySyncConfig c;
  c.station = {"demo", segment.rs4_address()};
  c.wall_at_zero = wall_at_zero(segment.now());
  return c;
}

}  // namespace

DemoProxy::DemoProxy(rs4::device::Rs4Segment& segment, storage::ParameterArchive& archive,
                     RunFor run_for)
    : segment_(segment), run_for_(std::move(run_for)), sync_(config(segment), archive) {}

proxy::RecordResult DemoProxy::exchange(const proxy::RecordRequest& request) {
  ++records_;
  const auto* w = std::get_if<proxy::RecordWrite>(&request);
  const auto r = w != nullptr ? segment_.write_record(w->data)
                              : segment_.read_record(std::get<proxy::RecordRead>(request).length);
  return r ? to_record_result(*r) : proxy::RecordResult::no_response();
}

bool DemoProxy::run_sync(dp::Duration timeout, const OnProgress& on_progress) {
  records_ = 0;
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
      if (on_progress) on_progress(sync_.progress());
    } else {
      run_for_(std::chrono::milliseconds(10));
      sync_.tick(segment_.now());
    }
  }
  return false;
}

}  // namespace rs4sim::app
