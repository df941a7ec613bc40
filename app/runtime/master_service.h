#pragma once
// `rs4sim master` as a runtime instance: the master side of N RS4s
// (rs4/device/rs4_master_station.h) as the one station the shell (app/runtime/shell.h) runs on a
// link, its report (app/runtime/master_report.h), and the seam for plugged-in services such as the
// parameter proxy: a MasterPlugin sees every master-side event right after the link call
// that produced it and acts on the station (Proxy-Enable, record write/read).
//
//   memory  the RS4s are simulated too, on the in-memory bus on the manual clock
//   pty / serial / udp  the RS4s are elsewhere (e.g. `rs4sim run --device rs4`)

#include "app/devices/device_registry.h"
#include "app/devices/gsd_station_file.h"
#include "app/runtime/master_gsd.h"
#include "app/runtime/master_report.h"
#include "app/runtime/shell.h"
#include "rs4/device/rs4_master_station.h"

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::app {

struct MasterServiceOptions {
  rs4::device::Rs4MasterStationConfig station;
  bool json = false;
  int simulated_boot_ms = 30000;  // --link memory: boot time of the simulated RS4s
  // GSD slaves polled after the RS4s, configured from their GSDs (app/runtime/master_gsd.h);
  // --link memory simulates them too (GsdStation).
  std::vector<GsdStationSpec> gsd_slaves;
  std::chrono::milliseconds gsd_watchdog{200};  // their Set_Prm DP watchdog
  // The likely cause the console gives when an RS4 stops answering in data exchange
  // (MasterReport::explain_lost_slaves); run_master sets it from the link (lost_slave_hint).
  std::string lost_hint;
};

// The likely cause of a lost slave on this link: on a pty or UDP (the slave a process on this
// machine) a starved process; on a serial port the line. Empty on the in-memory bus (the
// slaves share the master's clock).
[[nodiscard]] std::string lost_slave_hint(const LinkOptions& link);

class MasterPlugin {
 public:
  virtual ~MasterPlugin() = default;
  // Once, before the link starts.
  virtual void start(rs4::device::Rs4MasterStation& station, dp::TimePoint now) {
    (void)station, (void)now;
  }
  // Every master-side event in order (MasterCycle is the clock tick); `report` prints the
  // plugin's own events (MasterReport::custom).
  virtual void on_event(const rs4::device::Rs4MasterEvent& e,
                        rs4::device::Rs4MasterStation& station, MasterReport& report,
                        dp::TimePoint now) = 0;
  // The plugin's gRPC services (`rs4sim master --grpc`, docs/rpc.md); they live as long as
  // the plugin. stop_services(): the server has shut down, end what streams still wait for.
  virtual ServiceList services(const ServiceContext& context) {
    (void)context;
    return {};
  }
  virtual void stop_services() {}
};

class MasterService final : public DeviceInstance {
 public:
  // Throws std::invalid_argument / std::system_error for a bad configuration.
  MasterService(const MasterServiceOptions& options, LinkKind link, std::ostream& out);
  ~MasterService() override;

  // The plugin must outlive the service; add before start().
  void add_plugin(MasterPlugin& plugin) { plugins_.push_back(&plugin); }

  // ---- DeviceInstance ---------------------------------------------------------------------
  [[nodiscard]] std::vector<dp::Station*> stations() override;
  void start(dp::TimePoint now) override;
  [[nodiscard]] std::string describe() const override;
  void print_status(std::ostream& out, const dp::link::StationCounters& link) const override;
  // BusMaster (the stations as the master sees them) and the plugins' services (the proxy:
  // Proxy and Archive).
  ServiceList services(const ServiceContext& context) override;
  void stop_services() override;

  [[nodiscard]] rs4::device::Rs4MasterStation& station() { return station_; }
  [[nodiscard]] const rs4::device::Rs4MasterStation& station() const { return station_; }
  [[nodiscard]] gsd::GsdMasterSlaves& gsd_slaves() { return gsd_; }
  // Every RS4 in data exchange with its F-host in RUN, every GSD slave in data exchange with
  // the F-hosts of its F-modules in RUN.
  [[nodiscard]] bool healthy() const;

 private:
  class Forwarder;
  void dispatch(dp::TimePoint now);
  // The start lines (the master, its RS4s, its GSD slaves), printed once the loop runs: after
  // the lines of the run's own set-up (the pty path, "grpc:/http: listening on ...",
  // docs/http.md), which come after start().
  void announce() const;

  gsd::GsdMasterSlaves gsd_;  // before station_: its entries configure the master
  GsdMasterReport gsd_report_{gsd_};
  rs4::device::Rs4MasterStation station_;
  std::unique_ptr<Forwarder> forwarder_;
  LinkKind link_;
  bool json_;
  std::string lost_hint_;
  std::ostream& out_;
  std::optional<MasterReport> report_;
  std::vector<MasterPlugin*> plugins_;
  std::vector<rs4::device::Rs4MasterEvent> events_;
  dp::TimePoint last_now_{};
  dp::TimePoint started_at_{};
  mutable bool announced_ = false;
};

// Runs the master side on the link until Ctrl-C / --duration (memory: simulated RS4s and GSD
// stations for --duration simulated seconds, default 40). Returns the exit code: 0, or 1 for a
// link error (memory: 1 unless every RS4 ends in data exchange with PROFIsafe running and every
// GSD station in data exchange).
int run_master(const MasterServiceOptions& options, const LinkOptions& link, std::ostream& out,
               const std::vector<MasterPlugin*>& plugins = {});

}  // namespace rs4sim::app
