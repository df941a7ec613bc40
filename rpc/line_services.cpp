#include "rpc/line_services.h"

#include "rpc/service_support.h"
#include "rpc/status.h"

#include <chrono>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rs4sim::rpc {
namespace {

using LineFn = std::function<grpc::Status(dp::TimePoint)>;

constexpr std::uint32_t kMaxFaultDelayMs = 10'000;

// Checks the address (INVALID_ARGUMENT beyond a byte, NOT_FOUND for another device), then
// runs `fn` on the loop; after a change the event hub looks at the device again. The link
// needs no poke: a core whose deadline or transmit queue a setter moves wakes it itself
// ([stream/byte_device.h] point 4; tests/*/wake_test.cpp).
grpc::Status on_line(const LineContext& c, const std::string& kind, std::uint32_t address,
                     const LineFn& fn, bool changes) {
  if (address > 255) {
    return invalid_argument("address", std::to_string(address) + " is not a one-byte address");
  }
  if (address != c.address) {
    return not_found("no " + kind + " at address " + std::to_string(address) + " (this run's " +
                     kind + " answers to " + std::to_string(c.address) + ")");
  }
  grpc::Status result;
  c.executor.run([&] {
    const auto now = c.clock.now();
    result = fn(now);
    if (!changes) return;
    if (c.hub != nullptr) c.hub->poll(now);
  });
  return result;
}

// SetBlockedRequest.blocked as numbers 1..count, or the INVALID_ARGUMENT naming the entry.
std::variant<std::vector<std::uint16_t>, grpc::Status> numbers(const v1::SetBlockedRequest& in,
                                                               unsigned count, const char* what) {
  std::vector<std::uint16_t> out;
  for (int i = 0; i < in.blocked_size(); ++i) {
    const auto n = in.blocked(i);
    if (n == 0 || n > count) {
      return invalid_argument(
          "blocked[" + std::to_string(i) + "]",
          std::string(what) + " " + std::to_string(n) + " outside 1.." + std::to_string(count));
    }
    out.push_back(static_cast<std::uint16_t>(n));
  }
  return out;
}

grpc::Status check_delay(std::uint32_t ms, const char* field) {
  if (ms == 0 || ms > kMaxFaultDelayMs) {
    return invalid_argument(field, std::to_string(ms) + " ms outside 1..10000");
  }
  return grpc::Status::OK;
}

// "9-13,25-34" (the --blocked syntax), "none" when empty.
std::string ranges(const std::vector<std::uint16_t>& sorted) {
  std::string out;
  for (std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i;
    while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1) ++j;
    out += (out.empty() ? "" : ",") + std::to_string(sorted[i]);
    if (j > i) out += "-" + std::to_string(sorted[j]);
    i = j + 1;
  }
  return out.empty() ? "none" : out;
}

const char* on_off(bool b) { return b ? "on" : "off"; }

void set_last_frame(const TappedByteDevice& tap, v1::LastFrame& out) {
  const auto& f = tap.last_frame();
  out.set_frame(std::string(f.begin(), f.end()));
  if (const auto at = tap.last_sent()) out.set_sent_ns(to_ns(*at));
}

std::uint32_t whole_ms(stream::Duration d) {
  return static_cast<std::uint32_t>(
      std::chrono::duration_cast<std::chrono::milliseconds>(d).count());
}

// ---- GridScan ------------------------------------------------------------------------------

const char* power_name(gridscan::PowerState p) {
  switch (p) {
    case gridscan::PowerState::kOff: return "off";
    case gridscan::PowerState::kStarting: return "starting";
    case gridscan::PowerState::kReady: return "ready";
  }
  return "?";
}

const char* mode_name(gridscan::CommMode m) {
  switch (m) {
    case gridscan::CommMode::kPolling: return "polling";
    case gridscan::CommMode::kFullStreaming: return "full-streaming";
    case gridscan::CommMode::kReducedStreaming: return "reduced-streaming";
    case gridscan::CommMode::kStandBy: return "stand-by";
  }
  return "?";
}

const char* configuration_name(gridscan::Configuration c) {
  return c == gridscan::Configuration::kStatic ? "static" : "blanking";
}

const char* led_name(gridscan::Led l) {
  switch (l) {
    case gridscan::Led::kOff: return "off";
    case gridscan::Led::kOn: return "on";
    case gridscan::Led::kBlinkSlow: return "blink-slow";
    case gridscan::Led::kBlinkFast: return "blink-fast";
    case gridscan::Led::kBlink1Hz: return "blink-1hz";
  }
  return "?";
}

std::vector<std::uint16_t> elements_of(std::uint64_t mask, unsigned count) {
  std::vector<std::uint16_t> out;
  for (unsigned e = 1; e <= count && e <= 64; ++e) {
    if ((mask >> (e - 1U)) & 1U) out.push_back(static_cast<std::uint16_t>(e));
  }
  return out;
}

std::vector<std::string> gridscan_faults(const gridscan::GridScanDevice& d) {
  const auto& f = d.faults();
  std::vector<std::string> out;
  if (f.transmit.late.count() > 0) out.emplace_back("late-answer");
  if (f.wrong_seq) out.emplace_back("wrong-seq");
  if (f.direction_bit) out.emplace_back("direction-bit");
  if (f.bad_crc) out.emplace_back("bad-crc");
  if (d.scene().internal_failure) out.emplace_back("internal-failure");
  if (f.transmit.silent) out.emplace_back("silent");
  if (f.config_not_set) out.emplace_back("config-not-set");
  if (f.repeat_frames) out.emplace_back("repeat-frames");
  if (f.insert_frames) out.emplace_back("insert-frames");
  if (f.test_ignored) out.emplace_back("test-ignored");
  if (f.stuck_free != 0) out.emplace_back("stuck-free");
  if (f.mode_activation_fails) out.emplace_back("mode-activation-fails");
  return out;
}

// ---- METRON --------------------------------------------------------------------------------

const char* ossd_function_name(metron::OssdFunction f) {
  switch (f) {
    case metron::OssdFunction::kEnabled: return "enabled";
    case metron::OssdFunction::kDisabled: return "disabled";
    case metron::OssdFunction::kStandby: return "standby";
  }
  return "?";
}

std::vector<std::uint16_t> metron_blocked(const metron::Scene& s) {
  std::vector<std::uint16_t> out;
  for (std::uint16_t b = 1; b <= s.beams(); ++b) {
    if (s.interrupted(b)) out.push_back(b);
  }
  return out;
}

// The deprecated delay_ms (late_ms's old name), read and written on purpose for old clients.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
std::uint32_t old_delay_ms(const v1::MetronFaultRequest& in) { return in.delay_ms(); }
void set_old_delay_ms(v1::MetronState& out, std::uint32_t ms) { out.set_delay_ms(ms); }
#pragma GCC diagnostic pop

std::vector<std::string> metron_faults(const metron::Faults& f) {
  std::vector<std::string> out;
  if (f.transmit.silent) out.emplace_back("silent");
  if (f.transmit.late.count() > 0) out.emplace_back("late");
  if (f.bad_checksum) out.emplace_back("bad-checksum");
  if (f.wrong_node) out.emplace_back("wrong-node");
  if (f.truncate) out.emplace_back("truncate");
  return out;
}

// ---- Polaris -------------------------------------------------------------------------------

std::vector<std::string> polaris_faults(const polaris::Faults& f) {
  std::vector<std::string> out;
  if (f.bad_crc) out.emplace_back("bad-crc");
  if (f.transmit.silent) out.emplace_back("no-answer");
  if (f.transmit.late.count() > 0) out.emplace_back("late");
  return out;
}

// ---- On the simulated clock: Exchange, Receive (every device) ------------------------------

constexpr std::size_t kMaxExchangeBytes = 256;  // the longest frame of the three: a Modbus RTU ADU
                                                // [Modbus serial line V1.02 §2.5.1]
constexpr std::uint32_t kDefaultExchangeMs = 1000;
constexpr std::uint64_t kMaxSimulatedMs = 24ULL * 3600 * 1000;

grpc::Status needs_simulated_line(const std::string& kind) {
  return failed_precondition(
      "CLOCK", "simulated line",
      "this " + kind + " runs on a real-time link; Exchange and Receive need the simulated "
      "line (rs4sim run --device " + kind + " --link memory --grpc ...)");
}

void fill_frame(const stream::LineFrame& f, v1::ReceivedFrame& out) {
  out.set_frame(std::string(f.bytes.begin(), f.bytes.end()));
  out.set_start_ns(to_ns(f.start));
  out.set_end_ns(to_ns(f.end));
}

grpc::Status exchange_on(const LineContext& c, const std::string& kind,
                         const v1::ExchangeRequest& in, v1::ExchangeResponse& out) {
  if (in.request().empty() || in.request().size() > kMaxExchangeBytes) {
    return invalid_argument("request", std::to_string(in.request().size()) +
                                           " bytes outside 1..256 (the longest frame on the line)");
  }
  if (in.timeout_ms() > kMaxSimulatedMs) {
    return invalid_argument("timeout_ms", std::to_string(in.timeout_ms()) +
                                              " ms outside 0..86400000 (24 h; 0 = 1000)");
  }
  const std::uint32_t ms = in.timeout_ms() == 0 ? kDefaultExchangeMs : in.timeout_ms();
  const std::vector<std::uint8_t> request(in.request().begin(), in.request().end());
  return on_line(
      c, kind, in.address(),
      [&](dp::TimePoint) {
        if (c.line == nullptr) return needs_simulated_line(kind);
        const auto x = c.line->exchange(request, std::chrono::milliseconds(ms));
        if (c.hub != nullptr) c.hub->poll(c.line->now());
        out.set_sent_ns(to_ns(x.sent));
        out.set_arrived_ns(to_ns(x.arrived));
        out.set_answered(x.reply.has_value());
        if (x.reply) {
          out.set_reply(std::string(x.reply->bytes.begin(), x.reply->bytes.end()));
          out.set_reply_start_ns(to_ns(x.reply->start));
          out.set_reply_end_ns(to_ns(x.reply->end));
          out.set_reply_after_ns(to_ns(x.reply->end) - to_ns(x.sent));
        }
        out.set_now_ns(to_ns(c.line->now()));
        return grpc::Status::OK;
      },
      false);
}

grpc::Status receive_on(const LineContext& c, const std::string& kind,
                        const v1::ReceiveRequest& in, v1::ReceiveResponse& out) {
  if (in.wait_ms() > kMaxSimulatedMs) {
    return invalid_argument("wait_ms",
                            std::to_string(in.wait_ms()) + " ms outside 0..86400000 (24 h)");
  }
  return on_line(
      c, kind, in.address(),
      [&](dp::TimePoint) {
        if (c.line == nullptr) return needs_simulated_line(kind);
        if (in.wait_ms() > 0) {
          (void)c.line->run_until([] { return false; }, std::chrono::milliseconds(in.wait_ms()));
          if (c.hub != nullptr) c.hub->poll(c.line->now());
        }
        for (const auto& f : c.line->receive()) fill_frame(f, *out.add_frames());
        out.set_dropped(c.line->unsolicited_dropped());
        out.set_now_ns(to_ns(c.line->now()));
        return grpc::Status::OK;
      },
      false);
}

}  // namespace

// ==== GridScan ==============================================================================

grpc::Status GridScanService::GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                                       v1::GridScanState* out) {
  return on_line(
      c_, "GridScan", in->address(),
      [&](dp::TimePoint now) {
        out->set_address(c_.address);
        out->set_power(power_name(d_.power()));
        out->set_mode(mode_name(d_.mode()));
        out->set_configuration(configuration_name(d_.configuration()));
        out->set_elements(d_.elements());
        out->set_alignment_active(d_.alignment_active());
        const auto leds = d_.leds(now);
        out->set_led_rx_green(led_name(leds.rx_green));
        out->set_led_rx_red(led_name(leds.rx_red));
        out->set_led_tx_green(led_name(leds.tx_green));
        const auto& scene = d_.scene();
        out->set_door_position(scene.door_position);
        for (const auto e : elements_of(scene.blocked, d_.elements())) out->add_blocked(e);
        out->set_soiling(scene.soiling);
        const auto report = d_.current_report();
        out->set_report_door_position(report.door_position);
        out->set_report_interrupted(report.interrupted);
        out->set_report_internal_failure(report.internal_failure);
        out->set_report_maintenance(report.maintenance);
        for (const auto e : elements_of(report.elements, d_.elements())) {
          out->add_report_interrupted_elements(e);
        }
        for (const auto& f : gridscan_faults(d_)) out->add_faults_present(f);
        out->set_late_ms(whole_ms(d_.faults().transmit.late));
        const auto& k = d_.counters();
        auto* o = out->mutable_counters();
        o->set_frames(k.frames);
        o->set_answered(k.answered);
        o->set_comm_tests(k.comm_tests);
        o->set_streamed(k.streamed);
        o->set_dropped(k.dropped());
        o->set_truncated(k.truncated);
        o->set_oversized(k.oversized);
        o->set_bad_sync(k.bad_sync);
        o->set_bad_crc(k.bad_crc);
        o->set_bad_seq(k.bad_seq);
        o->set_unknown_id(k.unknown_id);
        o->set_direction_bit(k.direction_bit);
        o->set_busy(k.busy);
        o->set_not_ready(k.not_ready);
        o->set_restarts(k.restarts);
        o->set_mode_fallbacks(k.mode_fallbacks);
        for (const auto e : elements_of(d_.faults().stuck_free, d_.elements())) {
          out->add_stuck_free(e);
        }
        set_last_frame(c_.tap, *out->mutable_last_frame());
        out->set_now_ns(to_ns(now));
        return grpc::Status::OK;
      },
      false);
}

grpc::Status GridScanService::SetDoor(grpc::ServerContext*, const v1::SetDoorRequest* in,
                                      v1::Empty*) {
  return on_line(
      c_, "GridScan", in->address(),
      [&](dp::TimePoint) {
        if (in->position() > d_.elements()) {
          return invalid_argument("position",
                                  std::to_string(in->position()) + " outside 0.." +
                                      std::to_string(d_.elements()) +
                                      " (elements below the door edge; elements = open)");
        }
        d_.set_door_position(in->position());
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GridScanService::SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                                         v1::Empty*) {
  return on_line(
      c_, "GridScan", in->address(),
      [&](dp::TimePoint) {
        auto elements = numbers(*in, d_.elements(), "element");
        if (auto* bad = std::get_if<grpc::Status>(&elements)) return *bad;
        std::uint64_t mask = 0;
        for (const auto e : std::get<std::vector<std::uint16_t>>(elements)) {
          mask |= std::uint64_t{1} << (e - 1U);
        }
        d_.set_blocked(mask);
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GridScanService::SetSoiling(grpc::ServerContext*, const v1::SetSoilingRequest* in,
                                         v1::Empty*) {
  if (in->level() > 3) {
    return invalid_argument(
        "level",
        std::to_string(in->level()) + " outside 0..3 (clean .. heavy soiling, state bits 14..15)");
  }
  return on_line(
      c_, "GridScan", in->address(),
      [&](dp::TimePoint) {
        d_.set_soiling(static_cast<std::uint8_t>(in->level()));
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GridScanService::fault(const v1::GridScanFaultRequest& in, bool inject) {
  const auto which = in.fault();
  if (which == v1::GRID_SCAN_FAULT_UNSPECIFIED || !v1::GridScanFault_IsValid(which)) {
    return invalid_argument("fault", "a GRID_SCAN_FAULT_* value is required");
  }
  if (inject && which == v1::GRID_SCAN_FAULT_LATE_ANSWER) {
    if (auto bad = check_delay(in.late_ms(), "late_ms"); !bad.ok()) return bad;
  }
  if (which != v1::GRID_SCAN_FAULT_STUCK_FREE && in.elements_size() > 0) {
    return invalid_argument("elements", "only GRID_SCAN_FAULT_STUCK_FREE takes elements");
  }
  if (inject && which == v1::GRID_SCAN_FAULT_STUCK_FREE && in.elements_size() == 0) {
    return invalid_argument("elements", "GRID_SCAN_FAULT_STUCK_FREE needs the elements to stick");
  }
  return on_line(
      c_, "GridScan", in.address(),
      [&](dp::TimePoint) {
        std::uint64_t chosen = 0;
        for (const auto e : in.elements()) {
          if (e < 1 || e > d_.elements()) {
            return invalid_argument("elements", "element " + std::to_string(e) + " outside 1.." +
                                                    std::to_string(d_.elements()));
          }
          chosen |= std::uint64_t{1} << (e - 1U);
        }
        if (which == v1::GRID_SCAN_FAULT_INTERNAL_FAILURE) {
          d_.set_internal_failure(inject);
          return grpc::Status::OK;
        }
        auto f = d_.faults();
        switch (which) {
          case v1::GRID_SCAN_FAULT_LATE_ANSWER:
            f.transmit.late = inject ? stream::Duration(std::chrono::milliseconds(in.late_ms()))
                               : stream::Duration{};
            break;
          case v1::GRID_SCAN_FAULT_WRONG_SEQ: f.wrong_seq = inject; break;
          case v1::GRID_SCAN_FAULT_DIRECTION_BIT: f.direction_bit = inject; break;
          case v1::GRID_SCAN_FAULT_BAD_CRC: f.bad_crc = inject; break;
          case v1::GRID_SCAN_FAULT_SILENT: f.transmit.silent = inject; break;
          case v1::GRID_SCAN_FAULT_CONFIG_NOT_SET: f.config_not_set = inject; break;
          case v1::GRID_SCAN_FAULT_REPEAT_FRAMES: f.repeat_frames = inject; break;
          case v1::GRID_SCAN_FAULT_INSERT_FRAMES: f.insert_frames = inject; break;
          case v1::GRID_SCAN_FAULT_TEST_IGNORED: f.test_ignored = inject; break;
          case v1::GRID_SCAN_FAULT_STUCK_FREE:
            if (inject) {
              f.stuck_free |= chosen;
            } else {
              f.stuck_free &= chosen == 0 ? 0 : ~chosen;
            }
            break;
          case v1::GRID_SCAN_FAULT_MODE_ACTIVATION_FAILS: f.mode_activation_fails = inject; break;
          default: break;
        }
        d_.set_faults(f);
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GridScanService::InjectFault(grpc::ServerContext*, const v1::GridScanFaultRequest* in,
                                          v1::Empty*) {
  return fault(*in, true);
}

grpc::Status GridScanService::ClearFault(grpc::ServerContext*, const v1::GridScanFaultRequest* in,
                                         v1::Empty*) {
  return fault(*in, false);
}

grpc::Status GridScanService::PowerCycle(grpc::ServerContext*, const v1::PowerCycleRequest* in,
                                         v1::Empty*) {
  constexpr std::uint32_t kMaxOffMs = 3'600'000;
  if (in->off_ms() > kMaxOffMs) {
    return invalid_argument("off_ms", std::to_string(in->off_ms()) + " ms outside 0..3600000");
  }
  return on_line(
      c_, "GridScan", in->address(),
      [&](dp::TimePoint now) {
        if (in->off_ms() > 0 && c_.line == nullptr) return needs_simulated_line("gridscan");
        d_.power_off();
        if (in->off_ms() > 0) {
          (void)c_.line->run_until([] { return false; }, std::chrono::milliseconds(in->off_ms()));
          now = c_.line->now();
        }
        d_.power_on(now);
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GridScanService::SetPower(grpc::ServerContext*, const v1::SetPowerRequest* in,
                                       v1::Empty*) {
  return on_line(
      c_, "GridScan", in->address(),
      [&](dp::TimePoint now) {
        in->on() ? d_.power_on(now) : d_.power_off();
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GridScanService::Exchange(grpc::ServerContext*, const v1::ExchangeRequest* in,
                                       v1::ExchangeResponse* out) {
  return exchange_on(c_, "gridscan", *in, *out);
}

grpc::Status GridScanService::Receive(grpc::ServerContext*, const v1::ReceiveRequest* in,
                                      v1::ReceiveResponse* out) {
  return receive_on(c_, "gridscan", *in, *out);
}

// ==== METRON ================================================================================

namespace {

grpc::Status check_metron_address(std::uint32_t address) {
  if (address == metron::kBroadcast) {
    return invalid_argument("address",
                            "255 is the broadcast address [METRON manual \"With node\"]; the "
                            "curtain's is its node (0..254), or 0 without node mode");
  }
  return grpc::Status::OK;
}

}  // namespace

grpc::Status MetronService::GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                                     v1::MetronState* out) {
  if (auto bad = check_metron_address(in->address()); !bad.ok()) return bad;
  return on_line(
      c_, "METRON", in->address(),
      [&](dp::TimePoint now) {
        const auto& o = d_.options();
        const auto& scene = d_.scene();
        out->set_address(c_.address);
        out->set_line_mode(std::string(metron::to_string(o.line_mode)));
        out->set_node_enabled(o.node_enabled);
        out->set_beams(scene.beams());
        for (const auto b : metron_blocked(scene)) out->add_blocked(b);
        out->set_synchronised(scene.synchronised());
        out->set_input_high(scene.input_high());
        out->set_input_type(std::string(metron::to_string(d_.options().input_type)));
        out->set_ossd(d_.ossd_on());
        out->set_ossd_function(ossd_function_name(d_.slave_state().ossd));
        out->set_first_interrupted(scene.measure(metron::Measurement::kFirstInterrupted));
        out->set_last_interrupted(scene.measure(metron::Measurement::kLastInterrupted));
        out->set_interrupted_count(scene.measure(metron::Measurement::kInterruptedCount));
        for (const auto& f : metron_faults(d_.faults())) out->add_faults_present(f);
        out->set_late_ms(whole_ms(d_.faults().transmit.late));
        set_old_delay_ms(*out, out->late_ms());
        const auto k = d_.counters();
        auto* c = out->mutable_counters();
        c->set_messages(k.messages);
        c->set_executed(k.executed);
        c->set_frames_sent(k.frames_sent);
        for (const auto e : k.errors) c->add_errors(e);
        c->set_parity_rejected(k.parity_rejected);
        c->set_not_for_us(k.not_for_us);
        c->set_broadcast_ignored(k.broadcast_ignored);
        c->set_truncated(k.truncated);
        c->set_too_long(k.too_long);
        c->set_resets(k.resets);
        c->set_reports(k.reports);
        c->set_reports_dropped(k.reports_dropped);
        c->set_suppressed(k.suppressed);
        set_last_frame(c_.tap, *out->mutable_last_frame());
        out->set_now_ns(to_ns(now));
        return grpc::Status::OK;
      },
      false);
}

grpc::Status MetronService::SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                                       v1::Empty*) {
  if (auto bad = check_metron_address(in->address()); !bad.ok()) return bad;
  return on_line(
      c_, "METRON", in->address(),
      [&](dp::TimePoint) {
        auto beams = numbers(*in, d_.scene().beams(), "beam");
        if (auto* bad = std::get_if<grpc::Status>(&beams)) return *bad;
        d_.set_interrupted(std::get<std::vector<std::uint16_t>>(beams));
        return grpc::Status::OK;
      },
      true);
}

grpc::Status MetronService::SetSynchronised(grpc::ServerContext*,
                                            const v1::SetSynchronisedRequest* in, v1::Empty*) {
  if (auto bad = check_metron_address(in->address()); !bad.ok()) return bad;
  return on_line(
      c_, "METRON", in->address(),
      [&](dp::TimePoint) {
        d_.set_synchronised(in->synchronised());
        return grpc::Status::OK;
      },
      true);
}

grpc::Status MetronService::SetInput(grpc::ServerContext*, const v1::SetInputRequest* in,
                                     v1::Empty*) {
  if (auto bad = check_metron_address(in->address()); !bad.ok()) return bad;
  return on_line(
      c_, "METRON", in->address(),
      [&](dp::TimePoint) {
        d_.set_input(in->high());
        return grpc::Status::OK;
      },
      true);
}

grpc::Status MetronService::fault(const v1::MetronFaultRequest& in, bool inject) {
  if (auto bad = check_metron_address(in.address()); !bad.ok()) return bad;
  const auto which = in.fault();
  if (which == v1::METRON_FAULT_UNSPECIFIED || !v1::MetronFault_IsValid(which)) {
    return invalid_argument("fault", "a METRON_FAULT_* value is required");
  }
  // late_ms, or the deprecated delay_ms of older clients.
  const std::uint32_t old_ms = old_delay_ms(in);
  const bool old_name = in.late_ms() == 0 && old_ms != 0;
  const std::uint32_t late_ms = old_name ? old_ms : in.late_ms();
  if (in.late_ms() != 0 && old_ms != 0 && in.late_ms() != old_ms) {
    return invalid_argument("delay_ms", "the deprecated delay_ms " + std::to_string(old_ms) +
                                            " differs from late_ms " +
                                            std::to_string(in.late_ms()) + "; give late_ms only");
  }
  if (inject && which == v1::METRON_FAULT_LATE) {
    if (auto bad = check_delay(late_ms, old_name ? "delay_ms" : "late_ms"); !bad.ok()) return bad;
  }
  return on_line(
      c_, "METRON", in.address(),
      [&](dp::TimePoint) {
        auto& f = d_.faults();
        switch (which) {
          case v1::METRON_FAULT_SILENT: f.transmit.silent = inject; break;
          case v1::METRON_FAULT_LATE:
            f.transmit.late = inject ? stream::Duration(std::chrono::milliseconds(late_ms))
                                   : stream::Duration{};
            break;
          case v1::METRON_FAULT_BAD_CHECKSUM: f.bad_checksum = inject; break;
          case v1::METRON_FAULT_WRONG_NODE:
            if (inject && !d_.options().node_enabled) {
              return failed_precondition("MODE", "METRON " + std::to_string(c_.address),
                                         "a wrong node needs node mode (rs4sim run --node N)");
            }
            f.wrong_node = inject;
            break;
          case v1::METRON_FAULT_TRUNCATE: f.truncate = inject; break;
          default: break;
        }
        return grpc::Status::OK;
      },
      true);
}

grpc::Status MetronService::InjectFault(grpc::ServerContext*, const v1::MetronFaultRequest* in,
                                        v1::Empty*) {
  return fault(*in, true);
}

grpc::Status MetronService::ClearFault(grpc::ServerContext*, const v1::MetronFaultRequest* in,
                                       v1::Empty*) {
  return fault(*in, false);
}

grpc::Status MetronService::Exchange(grpc::ServerContext*, const v1::ExchangeRequest* in,
                                     v1::ExchangeResponse* out) {
  return exchange_on(c_, "metron", *in, *out);
}

grpc::Status MetronService::Receive(grpc::ServerContext*, const v1::ReceiveRequest* in,
                                    v1::ReceiveResponse* out) {
  return receive_on(c_, "metron", *in, *out);
}

// ==== Polaris ===============================================================================

namespace {

grpc::Status check_modbus_address(std::uint32_t address) {
  if (address == 0 || address > 247) {
    return invalid_argument("address", std::to_string(address) +
                                           " outside 1..247, the Modbus slave addresses "
                                           "[Modbus serial line V1.02 §2.2]");
  }
  return grpc::Status::OK;
}

}  // namespace

grpc::Status PolarisService::GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                                      v1::PolarisState* out) {
  if (auto bad = check_modbus_address(in->address()); !bad.ok()) return bad;
  return on_line(
      c_, "Polaris", in->address(),
      [&](dp::TimePoint now) {
        const auto& o = d_.options();
        out->set_address(c_.address);
        out->set_family(std::string(polaris::to_string(o.family)));
        out->set_beams(o.beams);
        out->set_data_mode(std::string(polaris::to_string(o.mode)));
        out->set_role(o.role == polaris::Role::kSlave ? "slave" : "master");
        for (const auto b : d_.interrupted()) out->add_blocked(b);
        out->set_pn1(d_.pn1());
        out->set_pn2(d_.pn2(now));
        out->set_start_address(polaris::start_address(o));
        for (const auto w : d_.data_block()) out->add_data_block(w);
        for (const auto& obj : d_.objects()) {
          auto* p = out->add_objects();
          p->set_first(obj.first);
          p->set_last(obj.last);
        }
        for (const auto& f : polaris_faults(d_.faults())) out->add_faults_present(f);
        out->set_late_ms(whole_ms(d_.faults().transmit.late));
        const auto& k = d_.counters();
        auto* c = out->mutable_counters();
        c->set_requests(k.requests);
        c->set_crc_errors(k.crc_errors);
        c->set_too_short(k.too_short);
        c->set_oversized(k.oversized);
        c->set_broadcasts(k.broadcasts);
        c->set_foreign_address(k.foreign_address);
        c->set_bad_function(k.bad_function);
        c->set_bad_request(k.bad_request);
        c->set_bad_start(k.bad_start);
        c->set_answers_ignored(k.answers_ignored);
        c->set_exceptions_sent(k.exceptions_sent);
        c->set_frames_sent(k.frames_sent);
        c->set_suppressed(k.suppressed);
        set_last_frame(c_.tap, *out->mutable_last_frame());
        out->set_now_ns(to_ns(now));
        return grpc::Status::OK;
      },
      false);
}

grpc::Status PolarisService::SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                                        v1::Empty*) {
  if (auto bad = check_modbus_address(in->address()); !bad.ok()) return bad;
  return on_line(
      c_, "Polaris", in->address(),
      [&](dp::TimePoint now) {
        auto beams = numbers(*in, d_.options().beams, "beam");
        if (auto* bad = std::get_if<grpc::Status>(&beams)) return *bad;
        if (const auto ec = d_.set_interrupted(std::get<std::vector<std::uint16_t>>(beams), now)) {
          return invalid_argument("blocked", ec.message());
        }
        return grpc::Status::OK;
      },
      true);
}

grpc::Status PolarisService::fault(const v1::PolarisFaultRequest& in, bool inject) {
  if (auto bad = check_modbus_address(in.address()); !bad.ok()) return bad;
  const auto which = in.fault();
  if (which == v1::POLARIS_FAULT_UNSPECIFIED || !v1::PolarisFault_IsValid(which)) {
    return invalid_argument("fault", "a POLARIS_FAULT_* value is required");
  }
  if (inject && which == v1::POLARIS_FAULT_LATE) {
    if (auto bad = check_delay(in.late_ms(), "late_ms"); !bad.ok()) return bad;
  }
  return on_line(
      c_, "Polaris", in.address(),
      [&](dp::TimePoint) {
        auto f = d_.faults();
        switch (which) {
          case v1::POLARIS_FAULT_BAD_CRC: f.bad_crc = inject; break;
          case v1::POLARIS_FAULT_SILENT: f.transmit.silent = inject; break;
          case v1::POLARIS_FAULT_LATE:
            f.transmit.late = inject ? stream::Duration(std::chrono::milliseconds(in.late_ms()))
                               : stream::Duration{};
            break;
          default: break;
        }
        d_.set_faults(f);
        return grpc::Status::OK;
      },
      true);
}

grpc::Status PolarisService::InjectFault(grpc::ServerContext*, const v1::PolarisFaultRequest* in,
                                         v1::Empty*) {
  return fault(*in, true);
}

grpc::Status PolarisService::ClearFault(grpc::ServerContext*, const v1::PolarisFaultRequest* in,
                                        v1::Empty*) {
  return fault(*in, false);
}

grpc::Status PolarisService::Exchange(grpc::ServerContext*, const v1::ExchangeRequest* in,
                                      v1::ExchangeResponse* out) {
  return exchange_on(c_, "polaris", *in, *out);
}

grpc::Status PolarisService::Receive(grpc::ServerContext*, const v1::ReceiveRequest* in,
                                     v1::ReceiveResponse* out) {
  return receive_on(c_, "polaris", *in, *out);
}

// ==== Watchers ==============================================================================

std::unique_ptr<Watcher> gridscan_watcher(std::uint8_t address, const gridscan::GridScanDevice& d) {
  return std::make_unique<ItemsWatcher>(address, [&d](dp::TimePoint now) {
    const auto leds = d.leds(now);
    const auto report = d.current_report();
    return ItemsWatcher::Items{
        {"power", power_name(d.power())},
        {"mode", mode_name(d.mode())},
        {"configuration", configuration_name(d.configuration())},
        {"led-rx-green", led_name(leds.rx_green)},
        {"led-rx-red", led_name(leds.rx_red)},
        {"led-tx-green", led_name(leds.tx_green)},
        {"door-position", std::to_string(report.door_position)},
        {"interrupted", on_off(report.interrupted)},
        {"internal-failure", on_off(report.internal_failure)},
        {"maintenance", std::to_string(report.maintenance)},
        {"elements", ranges(elements_of(report.elements, d.elements()))},
    };
  });
}

std::unique_ptr<Watcher> metron_watcher(std::uint8_t address, const metron::MetronDevice& d) {
  return std::make_unique<ItemsWatcher>(address, [&d](dp::TimePoint) {
    return ItemsWatcher::Items{
        {"ossd", on_off(d.ossd_on())},
        {"ossd-function", ossd_function_name(d.slave_state().ossd)},
        {"synchronised", on_off(d.scene().synchronised())},
        {"beams", ranges(metron_blocked(d.scene()))},
    };
  });
}

std::unique_ptr<Watcher> polaris_watcher(std::uint8_t address, const polaris::Device& d) {
  return std::make_unique<ItemsWatcher>(address, [&d](dp::TimePoint now) {
    return ItemsWatcher::Items{
        {"pn1", on_off(d.pn1())},
        {"pn2", on_off(d.pn2(now))},
        {"beams", ranges(d.interrupted())},
    };
  });
}

}  // namespace rs4sim::rpc
