// `rs4sim demo`, RS4 scenario (app/demos.h). Each step waits on the manual clock for what
// the manual prescribes and fails the demo if it does not happen (app/narration.h).
#include "app/demo_proxy.h"
#include "app/demos.h"
#include "app/narration.h"
#include "app/run_options.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_segment.h"
#include "rs4/protocol/telegram.h"
#include "rs4/scanner/faults.h"
#include "storage/sqlite_archive.h"

#include <cstdio>
#include <functional>
#include <ostream>
#include <string>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using rs4::adapter::kInputOssd;
using rs4::adapter::kInputProxyRequest;
using rs4::adapter::kOutputRestart;
using rs4::device::Rs4Segment;

class Demo {
 public:
  Demo(Rs4Segment& s, std::ostream& out)
      : s_(s),
        n_(
            out, s.clock(),
            [&s](const std::function<bool()>& done, dp::Duration limit) {
              return s.run_until(done, limit);
            },
            Narration::Stamp::kSeconds) {}

  void say(const std::string& text) const { n_.say(text); }
  bool wait(const std::function<bool()>& done, dp::Duration limit, const std::string& text) const {
    return n_.wait(done, limit, text);
  }
  bool ossd() const { return (s_.input_byte() & kInputOssd) != 0; }
  std::string input() const {
    const std::uint8_t b = s_.input_byte();
    return "input byte " + hex(std::span(&b, 1));
  }
  bool restart_pulse(std::uint8_t pair) {
    s_.set_output_byte(static_cast<std::uint8_t>(kOutputRestart | pair));
    s_.run_for(200ms);
    s_.set_output_byte(pair);
    if (!wait([&] { return ossd(); }, 500ms,
              "restart pulse 200 ms (output 8" + std::to_string(pair) + " → 0" +
                  std::to_string(pair) + "): OSSD bit 1")) {
      return false;
    }
    say("  " + input());
    return true;
  }
  Rs4Segment& s_;
  Narration n_;
};

bool startup(Demo& d) {
  Rs4Segment& s = d.s_;
  const auto& e = s.entry();
  d.say("RS4/PROFIsafe at address " + std::to_string(s.rs4_address()) +
        ", master from RSIM5234.gsd: Set_Prm user data " +
        hex(std::span(e.gsd.user_prm_data.data(), e.gsd.user_prm_data.size())) + ", Chk_Cfg " +
        hex(std::span(e.gsd.cfg.data(), e.gsd.cfg.size())));
  s.power_on();
  d.say("power on: adapter LED steady (init 2–3 s), RS4 boots (≈30 s)");
  if (!d.wait([&] { return s.in_data_exchange(); }, 5s,
              "DP start-up done: data exchange (LED off)"))
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
              "RS4 operational: Proxy-Request set, OSSD still 0 (start interlock)")) {
    return false;
  }
  d.say("  " + d.input());
  return d.restart_pulse(1);
}

bool protective_field(Demo& d) {
  Rs4Segment& s = d.s_;
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
  s.run_for(1s);
  if (d.ossd()) return false;
  return d.restart_pulse(1);
}

bool field_pairs(Demo& d) {
  Rs4Segment& s = d.s_;
  s.set_output_byte(0x02);
  if (!d.wait([&] { return s.device().scanner().status().first_pair == 2 && d.ossd(); }, 500ms,
              "field pair 1 → 2 (output 02): RS4 monitors pair 2, OSSD stays 1")) {
    return false;
  }
  s.set_output_byte(0x00);
  if (!d.wait([&] { return !d.ossd(); }, 200ms,
              "invalid field pair 0 (output 00): adapter error 0x2600, OSSD 0")) {
    return false;
  }
  s.run_for(300ms);
  s.set_output_byte(0x01);
  const auto at = s.now();
  if (!d.wait([&] { return d.ossd(); }, 1s, "valid pair 1 again: OSSD released")) return false;
  d.say("  after " + std::to_string(d.n_.ms_since(at)) + " ms (manual: ≈500 ms)");
  return true;
}

bool measurement(Demo& d) {
  Rs4Segment& s = d.s_;
  (void)s.device().scanner().edit_scene(s.now()).add(rs4::scanner::Circle{{0, 1500}, 100});
  s.run_for(100ms);
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
  const auto from = s.events().size();
  (void)s.device().scanner().inject_fault(rs4::scanner::Fault::kDazzled, s.now());
  d.say("RS4 error: receiver dazzled (error " +
        std::to_string(rs4::scanner::fault_info(rs4::scanner::Fault::kDazzled).error_number) + ")");
  if (!d.wait([&] { return alarm_of(s, 0x01, from) && !d.ossd(); }, 1s,
              "diagnosis alarm coming (type 1, 84 …), OSSD 0")) {
    return false;
  }
  (void)s.device().scanner().clear_fault(rs4::scanner::Fault::kDazzled, s.now());
  s.run_for(100ms);
  s.set_output_byte(kOutputRestart | 0x01);
  s.run_for(200ms);
  s.set_output_byte(0x01);
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
bool parameter_proxy(Demo& d, storage::ParameterArchive& archive) {
  Rs4Segment& s = d.s_;
  auto& adapter = s.device().adapter();
  auto& rs4 = s.device().scanner();
  auto set = rs4.parameters();
  set.response_steps = 2;  // T = 80 ms + 2·40 ms [RS4 manual §7.3]
  adapter.attach_pc_adapter(s.now());
  s.run_for(100ms);
  if (!rs4.enter_configuration(s.now()) || !rs4.set_parameters(set, s.now()) ||
      !rs4.leave_configuration(s.now())) {
    d.say("FAILED: the RS4 refused the new set");
    return false;
  }
  s.run_for(100ms);
  adapter.detach_pc_adapter(s.now());
  d.say("PC adapter attached, response time set to 160 ms through it, adapter removed");
  if (!d.wait([&] { return (s.input_byte() & kInputProxyRequest) != 0; }, 5s,
              "Proxy-Request: the set changed on site")) {
    return false;
  }
  DemoProxy proxy(s, archive);
  const auto at = s.now();
  if (!d.n_.check(proxy.run_sync(60s) && proxy.outputs() == proxy::FbOutputs{},
                  "proxy sync: the new set uploaded, compared and archived")) {
    return false;
  }
  auto station = DemoProxy::station();
  station.address = s.rs4_address();
  const auto current = archive.current(station);
  if (!current) return d.n_.check(false, "archive: " + current.error().message);
  char crc[12];
  std::snprintf(crc, sizeof crc, "0x%08X", current.value().version.crc32);
  d.say("  " + std::to_string(current.value().version.size) + " bytes in " +
        std::to_string(proxy.records()) + " DPV1 records, " + std::to_string(d.n_.ms_since(at)) +
        " ms; archive version " + std::to_string(current.value().version.number) + ", CRC-32 " +
        crc);
  return d.ossd() || d.restart_pulse(1);
}

}  // namespace

int run_rs4_demo(std::ostream& out, const DemoOptions& options) {
  rs4::device::Rs4SegmentConfig c;
  Rs4Segment s(c);
  const auto capture = open_capture(options.capture);
  attach_capture(capture.get(), s.bus());
  const std::string path = options.archive.empty() ? ":memory:" : options.archive;
  auto archive = storage::SqliteArchive::open(path);
  if (!archive) {
    out << "rs4sim: archive " << path << ": " << archive.error().message << std::endl;
    return 1;
  }
  Demo d(s, out);
  const bool ok = run_steps({[&] { return startup(d); }, [&] { return protective_field(d); },
                             [&] { return field_pairs(d); }, [&] { return measurement(d); },
                             [&] { return rs4_error(d); }, [&] { return passivation(d); },
                             [&] { return parameter_proxy(d, *archive.value()); }});
  d.say(ok ? "demo complete: every step as the manual prescribes" : "demo FAILED");
  if (capture) {
    d.say("capture: " + std::to_string(capture->records()) + " telegrams in " +
          options.capture.file);
  }
  if (!options.archive.empty()) d.say("archive: the demo's sets are in " + options.archive);
  out.flush();
  return ok ? 0 : 1;
}

}  // namespace rs4sim::app
