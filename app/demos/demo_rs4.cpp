// `rs4sim demo`, RS4 scenario (app/demos/demos.h). Each step waits on the manual clock for what
// the manual prescribes and fails the demo if it does not happen (app/demos/narration.h).
#include "app/demos/demo_proxy.h"
#include "app/demos/demos.h"
#include "app/runtime/run_session.h"
#include "app/demos/narration.h"
#include "app/runtime/progress_bar.h"
#include "app/runtime/run_options.h"
#include "rpc/rs4_services.h"
#include "rpc/segment_target.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_segment.h"
#include "rs4/protocol/telegram.h"
#include "rs4/scanner/faults.h"
#include "storage/open_archive.h"

#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using rs4::adapter::kInputOssd;
using rs4::adapter::kInputProxyRequest;
using rs4::adapter::kOutputProxyEnable;
using rs4::adapter::kOutputRestart;
using rs4::device::Rs4Segment;

// The process output byte of the demo's PLC: Proxy-Enable set (automatic parameter sync,
// [RS4 manual §5.1.2]) and the selected field pair.
constexpr std::uint8_t out_byte(std::uint8_t pair) {
  return static_cast<std::uint8_t>(kOutputProxyEnable | pair);
}

class Demo {
 public:
  Demo(Rs4Segment& s, storage::ParameterArchive& archive, std::ostream& out,
       const DemoOptions& options, RunSession& session)
      : s_(s),
        run_until_(run_until(s, options.realtime, session)),
        n_(out, s.clock(), run_until_, Narration::Stamp::kSeconds),
        proxy_(s, archive) {
    n_.set_live(options.live_progress);
  }

  void chapter(const std::string& title) const { n_.print("\n" + title + "\n"); }
  void say(const std::string& text) const { n_.say(text); }
  bool wait(const std::function<bool()>& done, dp::Duration limit, const std::string& text) const {
    return n_.wait(done, limit, text);
  }
  void run_for(dp::Duration d) const { n_.run_for(d); }
  bool ossd() const { return (s_.input_byte() & kInputOssd) != 0; }
  std::string input() const {
    const std::uint8_t b = s_.input_byte();
    return "input byte " + hex(std::span(&b, 1));
  }
  bool restart_pulse(std::uint8_t pair) {
    const auto pulse = static_cast<std::uint8_t>(kOutputRestart | out_byte(pair));
    s_.set_output_byte(pulse);
    run_for(200ms);
    s_.set_output_byte(out_byte(pair));
    if (!wait(
            [&] { return ossd(); }, 500ms,
            "restart pulse 200 ms (output " + hex(std::span(&pulse, 1)) + " for 200 ms): OSSD 1")) {
      return false;
    }
    say("  " + input());
    return true;
  }
  // One proxy sync from the current Proxy-Request, with a progress line; true when it ended.
  bool sync(const std::string& what) {
    const auto at = s_.now();
    proxy::SyncProgress last;
    const bool ended = proxy_.wait_sync(run_until_, 120s, [&](const proxy::SyncProgress& p) {
      if (p.bytes_total > 0) last = p;
      if (p.bytes_total > 0) n_.progress(line(what, p), false);
    });
    if (last.bytes_total > 0) {
      if (ended && proxy_.outputs().error_number_fb == 0) last.bytes_done = last.bytes_total;
      n_.progress(line(what, last), true);
    }
    if (!ended) return n_.check(false, what + ": the sync did not end within 120 s");
    say("  " + std::to_string(proxy_.records()) + " DPV1 records in " +
        std::to_string(n_.ms_since(at)) + " ms; FB outputs: " + fb_outputs());
    return true;
  }
  std::string fb_outputs() const {
    const auto& o = proxy_.outputs();
    char text[96];
    std::snprintf(text, sizeof text, "DONE, CONFIG_SET_TO_DEFAULT %d, ERROR_NUMBER_FB 0x%04X",
                  o.config_set_to_default ? 1 : 0, o.error_number_fb);
    return text;
  }

  Rs4Segment& s_;
  RunUntil run_until_;  // the story's time: paced, interruptible (in_session)
  Narration n_;
  DemoProxy proxy_;
  int response_ms_ = 0;  // the response time chapter 8 sets through the PC adapter

 private:
  static RunUntil run_until(Rs4Segment& s, bool realtime, RunSession& session) {
    RunUntil run = [&s](const std::function<bool()>& done, dp::Duration limit) {
      return s.run_until(done, limit);
    };
    return in_session(std::move(run), s.clock(), realtime, session);
  }
  static std::string line(const std::string& what, const proxy::SyncProgress& p) {
    return "  " + what + " " + progress_bar(p.bytes_done, p.bytes_total) + " " +
           std::to_string(p.bytes_done) + "/" + std::to_string(p.bytes_total) + " bytes";
  }
};

bool startup(Demo& d) {
  Rs4Segment& s = d.s_;
  const auto& e = s.entry();
  d.chapter("1. Power-up: PROFIBUS-DP and PROFIsafe start-up [RS4 manual §7.1.1]");
  d.say("RS4/PROFIsafe at address " + std::to_string(s.rs4_address()) +
        ", our master configured from RSIM5234.gsd: Set_Prm user data " +
        hex(std::span(e.gsd.user_prm_data.data(), e.gsd.user_prm_data.size())) + ", Chk_Cfg " +
        hex(std::span(e.gsd.cfg.data(), e.gsd.cfg.size())));
  s.set_output_byte(out_byte(1));
  s.power_on();
  d.say(
      "power on; the PLC sends output byte 41 (Proxy-Enable, field pair 1); the RS4 boots (≈30 s)");
  if (!d.wait([&] { return s.in_data_exchange(); }, 5s, "DP start-up done: data exchange"))
    return false;
  if (!d.wait(
          [&] { return s.fhost().state() == profisafe::FHostState::kRun && s.input_byte() != 0; },
          1s,
          "PROFIsafe: F_Dest_Add " + std::to_string(e.f_parameters.dest_add) +
              " accepted, F-host in RUN")) {
    return false;
  }
  d.say("  " + d.input() + " (bit 4: RS4 not yet operational, so OSSD 0)");
  if (!d.wait([&] { return (s.input_byte() & kInputProxyRequest) != 0; }, 31s,
              "RS4 operational: Proxy-Request (bit 2), OSSD held at 0 until the proxy answers")) {
    return false;
  }
  d.say("  " + d.input());
  return true;
}

// Scenario 1 of [RS4 manual §7.1, §7.2]: the archive has no set for this station, the RS4 runs
// on factory settings and the proxy says so with CONFIG_SET_TO_DEFAULT.
bool commissioning(Demo& d, storage::ParameterArchive& archive) {
  d.chapter("2. Commissioning: the parameter proxy [RS4 manual §7.1, §7.2]");
  // An archive kept from an earlier run (--archive FILE) already holds a set for this
  // station: then the new RS4 is a replacement and gets it (scenario 4).
  const bool known = archive.current(d.proxy_.station()).has_value();
  if (!d.sync(known ? "download" : "identify")) return false;
  if (known) {
    if (!d.n_.check(d.proxy_.outputs() == proxy::FbOutputs{}, "the download reported an error")) {
      return false;
    }
    d.say("  the archive already holds a set for this station: the RS4 got it (scenario 4)");
  } else {
    if (!d.n_.check(
            d.proxy_.outputs().config_set_to_default && d.proxy_.outputs().error_number_fb == 0,
            "first commissioning: expected CONFIG_SET_TO_DEFAULT 1 and no error")) {
      return false;
    }
    d.say("  the archive has no set for this RS4 and the RS4 has factory settings (scenario 1)");
  }
  return d.restart_pulse(1);
}

bool protective_field(Demo& d) {
  Rs4Segment& s = d.s_;
  d.chapter("3. Protective field violation and the restart interlock [RS4 manual §5.1.1]");
  auto id = s.device().scanner().edit_scene(s.now()).add(rs4::scanner::Circle{{0, 600}, 50});
  if (!id) return false;
  const auto at = s.now();
  d.say("object enters the protective field of pair 1 (Ø 100 mm at 600 mm, field 1000 mm)");
  if (!d.wait([&] { return !d.ossd(); }, 230ms,
              "OSSD bit 0 (T_R = 80 ms scanner + 150 ms F_WD_Time)"))
    return false;
  d.say("  after " + std::to_string(d.n_.ms_since(at)) + " ms, " + d.input() +
        " (bit 1: protective field violated)");
  (void)s.device().scanner().edit_scene(s.now()).remove(id.value());
  if (!d.wait([&] { return (s.input_byte() & rs4::adapter::kInputProtectiveField) == 0; }, 500ms,
              "object left: field free, OSSD stays 0 (restart interlock)")) {
    return false;
  }
  d.run_for(1s);
  if (!d.n_.check(!d.ossd(), "OSSD must stay 0 without a restart pulse")) return false;
  return d.restart_pulse(1);
}

bool field_pairs(Demo& d) {
  Rs4Segment& s = d.s_;
  d.chapter("4. Field-pair switching [RS4 manual §5.1.2]");
  s.set_output_byte(out_byte(2));
  if (!d.wait([&] { return s.device().scanner().status().first_pair == 2 && d.ossd(); }, 500ms,
              "field pair 1 → 2 (output 42): RS4 monitors pair 2, OSSD stays 1")) {
    return false;
  }
  s.set_output_byte(out_byte(0));
  if (!d.wait([&] { return !d.ossd(); }, 200ms,
              "invalid field pair 0 (output 40): adapter error 0x2600, OSSD 0")) {
    return false;
  }
  d.run_for(300ms);
  s.set_output_byte(out_byte(1));
  const auto at = s.now();
  if (!d.wait([&] { return d.ossd(); }, 1s, "valid pair 1 again: OSSD released")) return false;
  d.say("  after " + std::to_string(d.n_.ms_since(at)) + " ms (manual: ≈500 ms)");
  return true;
}

bool measurement(Demo& d) {
  Rs4Segment& s = d.s_;
  d.chapter("5. A measurement through the acyclic channel [RS4 manual §5.2]");
  (void)s.device().scanner().edit_scene(s.now()).add(rs4::scanner::Circle{{0, 1500}, 100});
  d.run_for(100ms);
  const std::uint8_t cmd[] = {0x92, 0x01, 0x00};
  d.say(
      "DPV1 WRITE slot 0 index 2: 00 07 FF FF 92 01 00 (PROFI_CMD_GET_RS4_DATA, measurement, "
      "once)");
  const auto answer = s.command(cmd);
  if (!answer) {
    d.say("FAILED: measurement telegram: " + answer.error().message());
    return false;
  }
  const auto tel = rs4::protocol::decode_telegram(answer.value());
  const auto* m = tel ? std::get_if<rs4::protocol::MeasurementTelegram>(&tel.value()) : nullptr;
  if (m == nullptr || m->values.size() != 529) {
    d.say("FAILED: the READ answer is not a 529-value 0x23 telegram");
    return false;
  }
  const auto& contour = s.device().scanner().last_scan().contour;
  std::size_t equal = 0;
  for (std::size_t i = 0; i < 529; ++i)
    equal += rs4::protocol::value_distance_mm(m->values[i]) == (contour[i] & 0xFFFE);
  d.say("READ blocks → 0x23 COM_CMD_MESS_16_RT, " + std::to_string(answer.value().size()) +
        " bytes: scan " + std::to_string(m->scan_number) + ", segments " +
        std::to_string(m->start) + ".." + std::to_string(m->stop) +
        ", 90° = " + std::to_string(rs4::protocol::value_distance_mm(m->values[264])) +
        " mm (object at 1400 mm), " + std::to_string(equal) +
        "/529 equal to the scanner's contour");
  return equal == 529;
}

bool alarm_of(Rs4Segment& s, std::uint8_t bits, std::size_t from) {
  for (std::size_t i = from; i < s.events().size(); ++i) {
    const auto* a = std::get_if<dp::master::AlarmReceived>(&s.events()[i]);
    if (a && a->alarm_type == 1 && (a->specifier & 0x03) == bits) return true;
  }
  return false;
}

bool rs4_error(Demo& d) {
  Rs4Segment& s = d.s_;
  d.chapter("6. An RS4 error as a diagnosis alarm [RS4 manual §5.3]");
  const auto from = s.events().size();
  (void)s.device().scanner().inject_fault(rs4::scanner::Fault::kDazzled, s.now());
  d.say("RS4 error: receiver dazzled (error " +
        std::to_string(rs4::scanner::fault_info(rs4::scanner::Fault::kDazzled).error_number) + ")");
  if (!d.wait([&] { return alarm_of(s, 0x01, from) && !d.ossd(); }, 1s,
              "diagnosis alarm coming (type 1, 84 …), OSSD 0")) {
    return false;
  }
  (void)s.device().scanner().clear_fault(rs4::scanner::Fault::kDazzled, s.now());
  d.run_for(100ms);
  s.set_output_byte(kOutputRestart | out_byte(1));
  d.run_for(200ms);
  s.set_output_byte(out_byte(1));
  if (!d.wait([&] { return !s.device().scanner().status().fault; }, 500ms,
              "cause gone; a restart pulse acknowledges the latched fault")) {
    return false;
  }
  if (!d.wait([&] { return alarm_of(s, 0x02, from); }, 2s,
              "diagnosis alarm going (≥ 500 ms without error)")) {
    return false;
  }
  return d.ossd() || d.restart_pulse(1);
}

bool passivation(Demo& d) {
  Rs4Segment& s = d.s_;
  d.chapter("7. PROFIsafe passivation and reintegration [PROFIsafe V1.30 F-host]");
  s.device().adapter().safety_faults().corrupt_crc2 = 1;
  d.say("one F-input PDU with a wrong CRC2 (fault injection on the device)");
  if (!d.wait([&] { return s.fhost().ack_req(); }, 500ms,
              "F-host passivated (substitute 0), communication healthy: ACK_REQ")) {
    return false;
  }
  s.ack_rei();
  return d.wait([&] { return s.fhost().state() == profisafe::FHostState::kRun && d.ossd(); }, 500ms,
                "ACK_REI: reintegrated, OSSD bit 1 again");
}

// Scenario 2 of [RS4 manual §7.1, §7.2]: a set changed on site through the PC adapter goes to the
// proxy when the adapter is removed; the proxy archives it (docs/proxy.md).
bool parameter_change(Demo& d, storage::ParameterArchive& archive) {
  Rs4Segment& s = d.s_;
  d.chapter("8. Parameters changed on site: the proxy archives the new set [RS4 manual §7.2]");
  auto& adapter = s.device().adapter();
  auto& rs4 = s.device().scanner();
  auto set = rs4.parameters();
  // T = 80 ms + n·40 ms [RS4 manual §6.6]: 160 ms, or 200 ms if an earlier run left 160 ms.
  set.response_steps = set.response_steps == 2 ? 3 : 2;
  d.response_ms_ = 80 + 40 * set.response_steps;
  adapter.attach_pc_adapter(s.now());
  d.run_for(100ms);
  if (!rs4.enter_configuration(s.now()) || !rs4.set_parameters(set, s.now()) ||
      !rs4.leave_configuration(s.now())) {
    return d.n_.check(false, "the RS4 refused the new set");
  }
  d.run_for(100ms);
  adapter.detach_pc_adapter(s.now());
  d.say("PC adapter attached, response time set to " + std::to_string(d.response_ms_) +
        " ms through it, adapter removed");
  if (!d.wait([&] { return (s.input_byte() & kInputProxyRequest) != 0; }, 5s,
              "Proxy-Request: the set changed on site")) {
    return false;
  }
  if (!d.sync("upload")) return false;
  if (!d.n_.check(d.proxy_.outputs() == proxy::FbOutputs{}, "the upload reported an error")) {
    return false;
  }
  const auto current = archive.current(d.proxy_.station());
  if (!current) return d.n_.check(false, "archive: " + current.error().message);
  char crc[12];
  std::snprintf(crc, sizeof crc, "0x%08X", current.value().version.crc32);
  d.say("  archived: version " + std::to_string(current.value().version.number) + ", " +
        std::to_string(current.value().version.size) + " bytes, CRC-32 " + crc +
        ", RS4 serial number " + current.value().version.serial_number);
  return d.ossd() || d.restart_pulse(1);
}

// Scenario 4 of [RS4 manual §7.1, §7.2]: a new RS4 with factory settings takes the old one's
// place; the proxy sees another serial number and downloads the archived set.
bool device_exchange(Demo& d, storage::ParameterArchive& archive) {
  Rs4Segment& s = d.s_;
  d.chapter("9. Device exchange: the archived set goes to the new RS4 [RS4 manual §7.1]");
  const auto archived = archive.current(d.proxy_.station());
  if (!archived) return d.n_.check(false, "archive: " + archived.error().message);
  s.power_off();
  d.run_for(2s);
  rs4::scanner::ScannerConfig unit;
  unit.identity.serial_number = 0x00054321;
  if (!d.n_.check(s.device().exchange_scanner(unit), "the RS4 could not be exchanged")) {
    return false;
  }
  s.power_on();
  d.say("power off, the RS4 replaced by a new unit (serial number " +
        std::to_string(unit.identity.serial_number) + ", factory settings), power on");
  if (!d.wait([&] { return s.in_data_exchange(); }, 5s, "DP start-up done: data exchange")) {
    return false;
  }
  if (!d.wait([&] { return s.fhost().ack_req(); }, 1s,
              "PROFIsafe: the F-host passivated on the communication loss: ACK_REQ")) {
    return false;
  }
  s.ack_rei();
  d.say("  the PLC acknowledges (ACK_REI)");
  if (!d.wait([&] { return (s.input_byte() & kInputProxyRequest) != 0; }, 35s,
              "the new RS4 is operational: Proxy-Request, OSSD 0")) {
    return false;
  }
  if (!d.sync("download")) return false;
  auto& rs4 = s.device().scanner();
  const bool restored = rs4.transfer_checksum() == archived.value().version.crc32 &&
                        80 + 40 * rs4.parameters().response_steps == d.response_ms_;
  if (!d.n_.check(d.proxy_.outputs() == proxy::FbOutputs{} && restored,
                  "the new RS4 did not get the archived set")) {
    return false;
  }
  const auto now_current = archive.current(d.proxy_.station());
  d.say("  the new RS4 runs the archived set (response time " + std::to_string(d.response_ms_) +
        " ms); the archive now names serial number " +
        (now_current ? now_current.value().version.serial_number : std::string("?")));
  return d.restart_pulse(1);
}

// The closing line: where the demo's sets are, under which bus, and the command that lists
// them (every `rs4sim archive` command defaults to bus "default"; the demo's is "demo").
std::string archive_line(const std::string& archive, const storage::StationKey& station) {
  if (archive.empty()) {
    return "archive: in memory only, gone with the demo (--archive FILE keeps its sets, under "
           "bus " + station.bus + ")";
  }
  const auto where = storage::display_location(archive);
  return "archive: the demo's sets are in " + where + ", bus " + station.bus + ": rs4sim archive "
         "history --archive '" + where + "' --bus " + station.bus + " --address " +
         std::to_string(station.address);
}

}  // namespace

int run_rs4_demo(RunSession& session, std::ostream& out, const DemoOptions& options) {
  rs4::device::Rs4SegmentConfig c;
  c.output_byte = out_byte(1);
  Rs4Segment s(c);
  const auto capture = open_capture(options.capture);
  attach_capture(capture.get(), s.bus());
  const std::string path = options.archive.empty() ? ":memory:" : options.archive;
  auto archive = storage::open_archive(path);
  if (!archive) {
    out << "rs4sim: archive: " << archive.error().message << std::endl;
    return 1;
  }
  storage::ParameterArchive& store = *archive.value();
  // --grpc: the API's calls run on this thread while the paced demo waits for the wall clock
  // (the session's loop runs in the waits), so they see the segment between two slices of the
  // story.
  std::optional<rpc::SegmentTarget> target;
  if (!options.grpc.empty()) {
    target.emplace(s);
    session.serve_grpc(options.grpc, ServiceList{std::make_shared<rpc::ObservationService>(
                                         rpc::Rs4Context{*target, session.executor()})});
    // The clients' streams end with the demo, before the server shuts down.
    session.on_stop_begin([&target] {
      if (auto* hub = target->events()) hub->close();
    });
  }
  Demo d(s, store, out, options, session);
  bool ok = false;
  bool interrupted = false;
  try {
    ok = run_steps({[&] { return startup(d); }, [&] { return commissioning(d, store); },
                    [&] { return protective_field(d); }, [&] { return field_pairs(d); },
                    [&] { return measurement(d); }, [&] { return rs4_error(d); },
                    [&] { return passivation(d); }, [&] { return parameter_change(d, store); },
                    [&] { return device_exchange(d, store); }});
    d.chapter(ok ? "demo complete: every step behaved as the manual prescribes"
                 : "demo FAILED (the step above)");
  } catch (const DemoInterrupted&) {
    interrupted = true;
    d.chapter("demo interrupted");
  }
  if (capture) {
    out << "capture: " << capture->records() << " telegrams in " << options.capture.file << "\n";
  }
  out << archive_line(options.archive, d.proxy_.station()) << "\n";
  session.finish();
  out.flush();
  if (interrupted) return kInterruptedExit;
  return ok ? 0 : 1;
}

}  // namespace rs4sim::app
