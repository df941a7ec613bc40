#pragma once
// The parameter proxy in the RS4 demo (app/demo_rs4.cpp): a proxy::ProxySync driven over the
// demo's simulated segment, record by record, with the archive as its store.

#include "proxy/proxy_sync.h"
#include "rs4/device/rs4_segment.h"
#include "storage/parameter_archive.h"

namespace rs4sim::app {

class DemoProxy {
 public:
  DemoProxy(rs4::device::Rs4Segment& segment, storage::ParameterArchive& archive);
  // Runs one sync from the current Proxy-Request to its end; false when none could start or
  // it did not end within `timeout` of simulated time.
  bool run_sync(dp::Duration timeout);
  [[nodiscard]] const proxy::FbOutputs& outputs() const { return sync_.outputs(); }
  [[nodiscard]] std::size_t records() const noexcept { return records_; }
  [[nodiscard]] static storage::StationKey station() { return {"demo", 4}; }

 private:
  proxy::RecordResult exchange(const proxy::RecordRequest& request);

  rs4::device::Rs4Segment& segment_;
  proxy::ProxySync sync_;
  std::size_t records_ = 0;
};

}  // namespace rs4sim::app
