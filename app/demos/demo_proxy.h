#pragma once
// The parameter proxy in the RS4 demo (app/demos/demo_rs4.cpp), hosted the way `rs4sim
// master` hosts it (app/runtime/master_proxy.h): a proxy::ProxyScheduler with the demo's RS4
// and a proxy::ProxyDriver whose records go out as DPV1 C1 WRITE/READ of slot 0, index 2
// through the segment's master ([RS4 manual §5.2]). It lives on the segment's master cycles
// (Rs4Segment::set_observer): every cycle it sees the RS4's input byte and polls the driver,
// so a Proxy-Request (input bit 2, [RS4 manual §5.1.1]) starts a sync whatever the story is
// doing, as on a PLC. The demo's chapters wait for it (wait_sync).

#include "app/demos/narration.h"
#include "proxy/proxy_driver.h"
#include "proxy/proxy_scheduler.h"
#include "rs4/device/rs4_segment.h"
#include "storage/parameter_archive.h"

#include <cstdint>
#include <functional>
#include <map>
#include <vector>

namespace rs4sim::app {

class DemoProxy final : private proxy::RecordChannel {
 public:
  using OnProgress = std::function<void(const proxy::SyncProgress&)>;

  // Registers itself as the segment's observer; the segment must outlive it.
  DemoProxy(rs4::device::Rs4Segment& segment, storage::ParameterArchive& archive);
  ~DemoProxy() override;
  DemoProxy(const DemoProxy&) = delete;
  DemoProxy& operator=(const DemoProxy&) = delete;

  // Runs the demo's time (through `run_until`) until a sync that is running now, or starts
  // within `timeout`, has ended, reporting its progress after every record; false when none
  // ended within `timeout` of simulated time.
  bool wait_sync(const RunUntil& run_until, dp::Duration timeout, const OnProgress& on_progress);
  [[nodiscard]] const proxy::FbOutputs& outputs() const;
  // Records exchanged by the last sync.
  [[nodiscard]] std::size_t records() const noexcept { return records_; }
  [[nodiscard]] const storage::StationKey& station() const;

 private:
  // proxy::RecordChannel
  void submit_write(std::uint8_t address, std::span<const std::uint8_t> record) override;
  void submit_read(std::uint8_t address, std::uint8_t length) override;
  void submitted(std::uint8_t address,
                 const boost::outcome_v2::std_result<dp::master::Dpv1RequestId>& id);
  void on_event(const dp::master::MasterEvent& e);
  void on_cycle(dp::TimePoint now);

  rs4::device::Rs4Segment& segment_;
  proxy::ProxyScheduler scheduler_;
  proxy::ProxyDriver driver_;
  proxy::ProxySync& sync_;  // the RS4's, owned by scheduler_
  std::map<dp::master::Dpv1RequestId, std::uint8_t> pending_;  // request id → RS4
  std::vector<std::uint8_t> refused_;  // requests the master refused at once: failed next cycle
  bool running_ = false;  // a sync is open (seen at the last cycle or its first record)
  std::size_t ended_ = 0;  // syncs ended so far
  std::size_t records_ = 0;
  OnProgress on_progress_;  // while wait_sync runs
};

}  // namespace rs4sim::app
