#pragma once
// The proxy parameter service inside `rs4sim master` (docs/master.md "Proxy"): one
// proxy::ProxySync per RS4 behind a proxy::ProxyScheduler (at most N syncs at a time), the
// archive as its store, and the records going out as DPV1 C1 WRITE/READ of slot 0, index 2
// through the master station ([RS4 manual §5.2]).

#include "app/runtime/master_service.h"
#include "proxy/proxy_driver.h"
#include "proxy/proxy_scheduler.h"
#include "rpc/archive_service.h"
#include "rpc/proxy_service.h"
#include "storage/parameter_archive.h"

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <string>

namespace rs4sim::app {

// The wall clock the proxy's archive writes are dated by (ProxySyncConfig::wall_clock; the
// cores read no clock): UTC now, in ms.
storage::Timestamp wall_now();
// A DPV1 outcome as the proxy sees it, with ERROR_CODE_SFC as the S7 RET_VAL W#16#80xx
// ([RS4 manual §6.4], proxy/record.h, [docs/decisions.md#proxy-error-code-sfc]).
proxy::RecordResult to_record_result(const dp::master::Dpv1Result& r);

struct ProxyPluginOptions {
  std::string bus = "default";   // the archive's bus name (as `rs4sim archive --bus`)
  std::size_t max_parallel = 1;  // N syncs at a time per bus ([RS4 manual §6.4, §6.5]: one)
  // --user/--site/--line/--skip-identical: what every stored version records.
  proxy::Recording recording{};
  // What --archive named: the Archive service's WatchVersions opens its own feed on it.
  std::string archive_location;
  // --link memory: the run's time is simulated (recorded beside each version), and the
  // retentive record stays in memory unless keep_proxy_state (--keep-proxy-state): the next
  // simulation starts as a new plant (docs/master.md "Proxy").
  bool simulated = false;
  bool keep_proxy_state = false;
};

// Where `rs4sim master` keeps its archive: `given` (--archive), else the user's default plant
// archive on a real link, else (--link memory) a private in-memory one, so a simulation never
// writes into the plant's archive unless asked.
std::string master_archive_location(const std::string& given, bool simulated);

class ProxyPlugin final : public MasterPlugin, private proxy::RecordChannel {
 public:
  ProxyPlugin(storage::ParameterArchive& archive, const ProxyPluginOptions& options);
  void start(rs4::device::Rs4MasterStation& station, dp::TimePoint now) override;
  void on_event(const rs4::device::Rs4MasterEvent& e, rs4::device::Rs4MasterStation& station,
                MasterReport& report, dp::TimePoint now) override;
  [[nodiscard]] const proxy::ProxyScheduler& scheduler() const noexcept { return scheduler_; }
  // Proxy (the FB outputs, the progress stream) and Archive over the archive it writes.
  ServiceList services(const ServiceContext& context) override;
  void stop_services() override;

 private:
  // proxy::RecordChannel
  void submit_write(std::uint8_t address, std::span<const std::uint8_t> record) override;
  void submit_read(std::uint8_t address, std::uint8_t length) override;
  void submitted(std::uint8_t address,
                 const boost::outcome_v2::std_result<dp::master::Dpv1RequestId>& id);
  void on_cycle(MasterReport& report, dp::TimePoint now);
  void report_changes(MasterReport& report, dp::TimePoint now);
  void report_status(MasterReport& report, const proxy::StationStatus& s, dp::TimePoint now);
  void publish_changes(dp::TimePoint now);

  storage::ParameterArchive& archive_;
  ProxyPluginOptions options_;
  proxy::ProxyScheduler scheduler_;
  proxy::ProxyDriver driver_;
  rs4::device::Rs4MasterStation* station_ = nullptr;
  std::map<dp::master::Dpv1RequestId, std::uint8_t> pending_;  // request id → RS4
  std::deque<std::uint8_t> refused_;  // requests the master refused at once, answered next cycle
  std::map<std::uint8_t, proxy::StationStatus> last_;
  // The API (services()): the feed of the Proxy service's streams, what it saw last.
  std::unique_ptr<rpc::ProxyFeed> feed_;
  std::shared_ptr<rpc::ArchiveService> archive_service_;
  std::map<std::uint8_t, proxy::StationStatus> published_;
};

}  // namespace rs4sim::app
