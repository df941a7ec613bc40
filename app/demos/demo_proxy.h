#pragma once
// The parameter proxy in the RS4 demo (app/demos/demo_rs4.cpp): one proxy::ProxySync (the
// Proxy-FB instance of the demo's RS4) driven over the demo's simulated segment, record by
// record, with the archive as its store.

#include "proxy/proxy_sync.h"
#include "rs4/device/rs4_segment.h"
#include "storage/parameter_archive.h"

#include <functional>

namespace rs4sim::app {

class DemoProxy {
 public:
  using RunFor = std::function<void(dp::Duration)>;
  using OnProgress = std::function<void(const proxy::SyncProgress&)>;

  // `run_for` moves the demo's simulated time (paced to the wall clock with --realtime).
  DemoProxy(rs4::device::Rs4Segment& segment, storage::ParameterArchive& archive, RunFor run_for);
  // Runs one sync from the current Proxy-Request to its end, reporting progress after every
  // record; false when none could start or it did not end within `timeout` of simulated time.
  bool run_sync(dp::Duration timeout, const OnProgress& on_progress);
  [[nodiscard]] const proxy::FbOutputs& outputs() const { return sync_.outputs(); }
  // Records exchanged by the last sync.
  [[nodiscard]] std::size_t records() const noexcept { return records_; }
  [[nodiscard]] const storage::StationKey& station() const { return sync_.station(); }

 private:
  proxy::RecordResult exchange(const proxy::RecordRequest& request);

  rs4::device::Rs4Segment& segment_;
  RunFor run_for_;
  proxy::ProxySync sync_;
  std::size_t records_ = 0;
};

}  // namespace rs4sim::app
