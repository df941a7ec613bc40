// `rs4sim master`: the master side users deploy — our class 1 master and a PROFIsafe
// F-host per RS4, configured from the GSD, on any link (app/runtime/master_service.h, docs/master.md).
//
//   rs4sim master --slave 4 --link serial --port /dev/pts/3       (an `rs4sim run --link pty`)
//   rs4sim master --slave 4 --slave 5 --link pty                  (prints its pty path first)
//   rs4sim master --slave 4 --link udp --listen 127.0.0.1:5000 --peer 127.0.0.1:5001
//   rs4sim master --slave 4 --slave 5 --link memory --json        (simulated RS4s, simulated time)
//   rs4sim master --slave 4 --link serial --port /dev/pts/3 --grpc 127.0.0.1:0  (Proxy, Archive)
//   rs4sim master --slave 4 --link serial --port /dev/pts/3 --restart-pulse 300
//                                                   (the start interlock's reset signal by the bus)
//   rs4sim master --gsd-slave 5:X.gsd --module "5:DI 8" --slave 4 --link serial --port ...
//                                                   (a GSD slave beside the RS4, master_gsd.h)
//   rs4sim master --bus-file bus.json --manual-ack --link serial --port /dev/pts/3 --grpc ...
//                 (the stations of `rs4sim run --bus bus.json`: RS4s and GSD F-devices, each
//                  PROFIsafe F-module with our F-host, docs/profisafe.md)
#include "app/cli/command.h"
#include "app/runtime/archive_path.h"
#include "app/runtime/author.h"
#include "app/runtime/grpc_cli.h"
#include "app/cli/link_cli.h"
#include "app/devices/gsd_segment.h"  // fit_max_tsdr
#include "app/runtime/master_gsd.h"
#include "app/runtime/master_proxy.h"
#include "app/runtime/master_service.h"
#include "dp/master/master_config.h"
#include "dp/pdu/sap.h"
#include "rpc/master_plc.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "storage/open_archive.h"
#include "storage/request_check.h"
#include "storage/sqlite_archive.h"  // default_archive_path

#include <charconv>
#include <iostream>
#include <memory>

namespace rs4sim::app {
namespace {

struct MasterCliOptions {
  std::vector<int> slaves;
  std::vector<std::string> gsd_slaves;   // ADDR:FILE
  std::vector<std::string> gsd_modules;  // ADDR:NAME, slot order per address
  std::vector<std::string> gsd_f_dest_adds;  // ADDR:N
  std::string bus_file;                  // --bus-file FILE.json
  int address = 1;
  std::optional<int> f_wd_time_ms;
  std::optional<int> f_source_add;
  std::vector<std::string> params;  // NAME=VALUE
  int dp_watchdog_ms = 200;
  std::optional<int> slot_time_bits;
  int cycle_ms = 10;
  int field_pair = 1;
  bool proxy_enable = false;
  bool no_proxy = false;
  std::string archive;  // empty: storage::default_archive_path()
  ProxyPluginOptions proxy;
  std::string user;  // --user; empty: the OS user
  bool manual_ack = false;
  std::optional<int> restart_pulse_ms;  // --restart-pulse
  MasterServiceOptions service;
  LinkOptions link;
};

gsd::ParamOverride parse_param(const std::string& text) {
  const auto eq = text.find('=');
  const std::string name = text.substr(0, eq);
  std::int64_t value = 0;
  const char* first = eq == std::string::npos ? nullptr : text.data() + eq + 1;
  const char* last = text.data() + text.size();
  const auto [p, ec] = first == nullptr
                           ? std::from_chars_result{nullptr, std::errc::invalid_argument}
                           : std::from_chars(first, last, value);
  if (name.empty() || ec != std::errc{} || p != last || first == last) {
    throw UsageError("--param " + text +
                     ": use NAME=VALUE with a decimal value, e.g. F_WD_Time=200");
  }
  return {name, value};
}

std::uint8_t checked(int value, int low, int high, const std::string& what) {
  if (value < low || value > high) {
    throw UsageError(what + ": " + std::to_string(value) + " is outside " + std::to_string(low) +
                     ".." + std::to_string(high));
  }
  return static_cast<std::uint8_t>(value);
}

// Slot time (bit times) of a real-time link: the OS's latency, not the wire's, decides
// there, so the longest slot time [IEC 61158-4-3 bus parameters, timing] allows.
constexpr std::uint32_t kRealtimeSlotBits = 16383;

dp::master::BusParameters bus_parameters(const MasterCliOptions& o,
                                         const std::vector<GsdStationSpec>& gsd) {
  const auto baud = dp::parse_baud_rate(o.link.baud);
  if (!baud) {
    throw UsageError("--baud " + o.link.baud + ": not a PROFIBUS rate; use one of " +
                     dp::standard_baud_rate_list());
  }
  auto bus = dp::master::BusParameters::defaults_for(*baud);
  // The slowest responder a GSD declares at this rate ([PROFIBUS GSD spec] MaxTsdr_<rate>):
  // on the memory bus the slot time grows with it (fit_max_tsdr); a real-time link's slot time
  // is the longest already.
  for (const auto& spec : gsd) {
    if (const auto t = gsd_max_tsdr(spec, o.link.baud)) fit_max_tsdr(bus, *t);
  }
  if (is_realtime(o.link.link)) bus.tsl = kRealtimeSlotBits;
  if (o.slot_time_bits) bus.tsl = static_cast<std::uint32_t>(*o.slot_time_bits);
  if (dp::master::validate(bus)) {
    throw UsageError(
        "--slot-time " + std::to_string(bus.tsl) +
        ": outside max TSDR + 15 .. 16383 bit ([IEC 61158-4-3 bus parameters, timing])");
  }
  return bus;
}

rs4::device::Rs4MasterStationConfig station_config(const MasterCliOptions& o,
                                                   const std::vector<GsdStationSpec>& gsd) {
  rs4::device::Rs4MasterStationConfig c;
  c.master_address = checked(o.address, 0, dp::pdu::sap::kMaxStationAddress, "--address");
  c.bus = bus_parameters(o, gsd);
  c.cycle_target = std::chrono::milliseconds(checked(o.cycle_ms, 1, 255, "--cycle"));
  c.auto_ack_rei = !o.manual_ack;
  c.output_byte = checked(o.field_pair, 1, 4, "--field-pair");
  if (o.proxy_enable && o.no_proxy) c.output_byte |= rs4::adapter::kOutputProxyEnable;
  const std::vector<int> slaves =
      o.slaves.empty() && gsd.empty() ? std::vector<int>{4} : o.slaves;
  for (const int s : slaves) {
    rs4::device::Rs4MasterOptions r;
    // [RS4 manual §4.5]: 0..126 on the switches; the master polls 0..125.
    r.address = checked(s, 0, dp::pdu::sap::kMaxSlaveAddress, "--slave");
    for (const auto& earlier : c.slaves) {
      if (earlier.address == r.address)
        throw UsageError("--slave " + std::to_string(s) + " given twice");
    }
    if (r.address == c.master_address) {
      throw UsageError("--slave " + std::to_string(s) + ": that is the master's --address");
    }
    r.dp_watchdog = std::chrono::milliseconds(o.dp_watchdog_ms);
    if (o.f_wd_time_ms) r.f_wd_time_ms = static_cast<std::uint16_t>(*o.f_wd_time_ms);
    if (o.f_source_add) r.overrides.push_back({"F_Source_Add", *o.f_source_add});
    for (const auto& p : o.params) r.overrides.push_back(parse_param(p));
    c.slaves.push_back(r);
  }
  for (const auto& g : gsd) {
    for (const auto& r : c.slaves) {
      if (r.address == g.address) {
        throw UsageError("--gsd-slave " + std::to_string(g.address) + ":" + g.file +
                         ": address " + std::to_string(g.address) + " is already --slave " +
                         std::to_string(r.address) + " (an RS4)");
      }
    }
    if (g.address == c.master_address) {
      throw UsageError("--gsd-slave " + std::to_string(g.address) + ":" + g.file +
                       ": that is the master's --address");
    }
  }
  return c;
}

// --bus-file: its RS4s join --slave, its GSD stations --gsd-slave (an address twice is refused
// by station_config or here).
void add_bus_file(MasterCliOptions& o) {
  auto bus = read_master_bus_file(o.bus_file, o.link.baud);
  o.slaves.insert(o.slaves.end(), bus.rs4s.begin(), bus.rs4s.end());
  for (auto& spec : bus.gsd) {
    for (const auto& g : o.service.gsd_slaves) {
      if (g.address == spec.address) {
        throw UsageError("--bus-file " + o.bus_file + ": address " +
                         std::to_string(spec.address) + " is already the GSD slave of " + g.file);
      }
    }
    o.service.gsd_slaves.push_back(std::move(spec));
  }
}

// rs4sim.v1.Plc and --restart-pulse (rpc/master_plc.h): what the PLC program writes, on the
// master's cycles.
class PlcPlugin final : public MasterPlugin {
 public:
  explicit PlcPlugin(std::optional<dp::Duration> restart_pulse) : plc_(restart_pulse) {}
  void start(rs4::device::Rs4MasterStation& station, dp::TimePoint now) override {
    plc_.attach(station);
    plc_.on_cycle(now);
  }
  void on_event(const rs4::device::Rs4MasterEvent& e, rs4::device::Rs4MasterStation&,
                MasterReport&, dp::TimePoint now) override {
    if (std::holds_alternative<rs4::device::MasterCycle>(e)) plc_.on_cycle(now);
  }
  ServiceList services(const ServiceContext& context) override {
    return {std::make_shared<rpc::PlcService>(plc_, context.executor)};
  }

 private:
  rpc::MasterPlc plc_;
};

std::optional<dp::Duration> restart_pulse(const MasterCliOptions& o) {
  if (!o.restart_pulse_ms) return std::nullopt;
  // [RS4 manual §4.3]: the RS4 takes a press of 0.12..5 s as the reset signal.
  const int ms = *o.restart_pulse_ms;
  if (ms < 120 || ms > 5000) {
    throw UsageError("--restart-pulse: " + std::to_string(ms) +
                     " ms is outside 120..5000 (what the RS4 takes as a reset signal)");
  }
  return std::chrono::milliseconds(ms);
}

int run(MasterCliOptions& o) {
  validate(o.link);
  std::vector<std::string> warnings;
  o.service.gsd_slaves = parse_gsd_slaves(o.gsd_slaves, o.gsd_modules, o.link.baud, &warnings);
  for (const auto& w : warnings) std::cerr << "warning: " << w << std::endl;
  apply_gsd_f_dest_adds(o.service.gsd_slaves, o.gsd_f_dest_adds);
  if (!o.bus_file.empty()) add_bus_file(o);
  if (o.f_wd_time_ms) apply_gsd_f_wd_time(o.service.gsd_slaves, *o.f_wd_time_ms);
  o.service.gsd_watchdog = std::chrono::milliseconds(o.dp_watchdog_ms);
  o.service.station = station_config(o, o.service.gsd_slaves);
  if (o.proxy_enable && !o.no_proxy) {
    throw UsageError("--proxy-enable is for --no-proxy runs; the proxy sets Proxy-Enable itself");
  }
  if (o.proxy.max_parallel == 0) throw UsageError("--max-syncs must be at least 1");
  auto& recording = o.proxy.recording;
  recording.author = local_author(o.user);
  const std::pair<const char*, const std::string*> texts[] = {
      {"user", &recording.author.user}, {"site", &recording.site}, {"line", &recording.line}};
  for (const auto& [name, value] : texts) {
    const auto ok = storage::check_text(name, *value, storage::kMaxNameSize);
    if (!ok) throw UsageError("--" + ok.error().message);
  }
  const std::string api = o.link.grpc.address.empty() ? "--http" : "--grpc";
  if (!o.link.grpc.empty() && o.link.link == LinkKind::kMemory) {
    throw UsageError(
        api + ": the master serves its API on a real-time link (pty, serial, "
        "udp); for a simulated bus under API control use `rs4sim run --link "
        "memory " + api + "`");
  }
  if (!o.link.grpc.empty() && o.no_proxy && o.service.gsd_slaves.empty()) {
    throw UsageError(api + " serves the proxy and its archive, which --no-proxy turns off");
  }
  std::unique_ptr<storage::ParameterArchive> archive;
  std::unique_ptr<ProxyPlugin> proxy;
  PlcPlugin plc(restart_pulse(o));
  std::vector<MasterPlugin*> plugins{&plc};
  if (!o.no_proxy) {
    o.proxy.simulated = o.link.link == LinkKind::kMemory;
    const std::string path = master_archive_location(
        o.archive.empty() ? "" : checked_archive_path(o.archive), o.proxy.simulated);
    if (path == ":memory:") {
      std::cerr << "rs4sim: --link memory: the proxy's archive is in memory only (--archive FILE "
                   "keeps its versions, --keep-proxy-state its retentive state)\n";
    }
    auto opened = storage::open_archive(path);
    if (!opened) {
      std::cerr << "rs4sim: archive: " << opened.error().message << std::endl;
      return 1;
    }
    archive = std::move(opened).value();
    o.proxy.archive_location = path;
    proxy = std::make_unique<ProxyPlugin>(*archive, o.proxy);
    plugins.push_back(proxy.get());
  }
  try {
    return run_master(o.service, o.link, std::cout, plugins);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());  // a GSD override the GSD refuses, a duplicate --slave
  } catch (const std::system_error& e) {
    throw UsageError(std::string("master configuration: ") + e.what());
  }
}

Action setup(CLI::App& cmd) {
  auto o = std::make_shared<MasterCliOptions>();
  LinkOptions& l = o->link;
  cmd.add_option("--slave", o->slaves, "an RS4's DP address; repeat for more (default 4 unless --gsd-slave is given)");
  cmd.add_option("--gsd-slave", o->gsd_slaves,
                 "ADDRESS:FILE: a DP slave configured from its GSD file (Set_Prm with the GSD's "
                 "default User_Prm_Data, Chk_Cfg from its modules); repeatable");
  cmd.add_option("--module", o->gsd_modules,
                 "ADDRESS:NAME: a module of that --gsd-slave by its GSD name, repeat it in slot "
                 "order (a compact station's one module is implicit)");
  cmd.add_option("--gsd-f-dest-add", o->gsd_f_dest_adds,
                 "ADDRESS:N: the F_Dest_Add written into the PROFIsafe F-modules of that "
                 "--gsd-slave (its address switch; default: the GSD's); repeatable");
  cmd.add_option("--bus-file", o->bus_file,
                 "FILE.json: poll the stations of a bus file (`rs4sim run --bus`): its RS4s as "
                 "--slave, its GSD stations as --gsd-slave with their \"f-dest-add\"");
  cmd.add_option("--address", o->address, "the master's own FDL address (default 1)");
  cmd.add_option("--f-wd-time", o->f_wd_time_ms,
                 "F_WD_Time in ms for every RS4 (default 150) and every GSD slave's PROFIsafe "
                 "F-module (default: its GSD's)")
      ->check(CLI::Range(1, 65535));
  cmd.add_option("--f-source-add", o->f_source_add, "F_Source_Add (GSD default otherwise)")
      ->check(CLI::Range(1, 65534));
  cmd.add_option("--param", o->params,
                 "GSD parameter override NAME=VALUE for every RS4, e.g. F_SIL=2; repeatable");
  cmd.add_option("--dp-watchdog", o->dp_watchdog_ms, "DP watchdog in ms (Set_Prm, default 200)")
      ->check(CLI::Range(10, 650250));
  cmd.add_option("--slot-time", o->slot_time_bits,
                 "slot time TSL in bit times (default: the baud's table value on memory, "
                 "16383 on real-time links)");
  cmd.add_option("--cycle", o->cycle_ms, "target master cycle in ms (default 10)");
  cmd.add_option("--field-pair", o->field_pair, "field pair 1..4 in the output byte (default 1)");
  cmd.add_flag("--no-proxy", o->no_proxy,
               "run without the parameter proxy (default: the proxy syncs every RS4's set with "
               "the archive and sets Proxy-Enable)");
  cmd.add_flag("--proxy-enable", o->proxy_enable,
               "with --no-proxy: set Proxy-Enable anyway (the RS4s then wait for a proxy)");
  cmd.add_option("--archive", o->archive,
                 "the parameter archive (default $XDG_DATA_HOME/rs4sim/archive.sqlite3; on "
                 "--link memory one in memory only)");
  cmd.add_flag("--keep-proxy-state", o->proxy.keep_proxy_state,
               "--link memory: keep the proxy's retentive state in the archive for the next "
               "simulation (a real link always keeps it)");
  cmd.add_option("--bus", o->proxy.bus, "the bus name under which the archive keeps the RS4s")
      ->capture_default_str();
  cmd.add_option("--max-syncs", o->proxy.max_parallel,
                 "syncs at a time on this bus (default 1, as the manual advises)");
  cmd.add_option("--user", o->user,
                 "the user every archived version records (default: the OS user)");
  cmd.add_option("--site", o->proxy.recording.site,
                 "the plant site this bus belongs to, recorded with its stations");
  cmd.add_option("--line", o->proxy.recording.line,
                 "the production line within the site, recorded with its stations");
  cmd.add_flag("--skip-identical", o->proxy.recording.skip_identical,
               "store no new version when an uploaded set is the station's current one");
  cmd.add_flag("--manual-ack", o->manual_ack,
               "keep ACK_REQ standing after a PROFIsafe fault (default: acknowledge at once)");
  cmd.add_option("--restart-pulse", o->restart_pulse_ms,
                 "MS: pulse the restart bit for MS ms (120..5000) once per start-up of each RS4, "
                 "when it waits in its start interlock (OSSD 0, operational, field free)");
  cmd.add_option("--boot-time", o->service.simulated_boot_ms,
                 "memory: boot time of the simulated RS4s in ms (default 30000)")
      ->check(CLI::Range(0, 600000));
  cmd.add_flag("--json", o->service.json, "one JSON object per line for every event");
  add_link_options(cmd, l, LinkCommand::kMaster);
  add_grpc_options(cmd, l.grpc,
                   "the Proxy and Archive services, GsdMaster with --gsd-slave (real-time links)");
  return [o]() -> int { return run(*o); };
}

const CommandRegistration kMaster(
    "master",
    "run our class 1 master + PROFIsafe F-host for RS4s, and GSD slaves, on a link (memory, pty, "
    "serial, udp)",
    setup,
    Signals::kSession);

}  // namespace
}  // namespace rs4sim::app
