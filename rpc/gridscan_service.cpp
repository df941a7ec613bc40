#include "rpc/gridscan_service.h"

#include "gridscan/description.h"
#include "rpc/line_devices.h"
#include "rpc/service_support.h"
#include "rpc/status.h"

#include <chrono>
#include <string>
#include <variant>
#include <vector>

namespace rs4sim::rpc {
namespace {

using line::check_delay;
using line::needs_simulated_line;
using line::numbers;
using line::on_off;
using line::ranges;
using line::set_line_state;
using line::token_of;

using gridscan::elements_of;

std::int64_t ns(stream::Duration d) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(d).count();
}

}  // namespace

GridScanService::GridScanService(LineContext context, gridscan::Device& device)
    : LineService(context, "GridScan", nullptr), d_(device) {}

grpc::Status GridScanService::GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                                       v1::GridScanState* out) {
  return on_device(
      in->address(),
      [&](dp::TimePoint now) {
        out->set_address(c_.address);
        out->set_power(token_of(d_.power()));
        out->set_mode(token_of(d_.mode()));
        out->set_configuration(token_of(d_.configuration()));
        out->set_elements(d_.elements());
        out->set_alignment_active(d_.alignment_active());
        const auto leds = d_.leds(now);
        out->set_led_rx_green(token_of(leds.rx_green));
        out->set_led_rx_red(token_of(leds.rx_red));
        out->set_led_tx_green(token_of(leds.tx_green));
        const auto& scene = d_.scene();
        out->set_door_position(scene.door_position);
        for (const auto e : d_.interrupted()) out->add_blocked(e);
        out->set_soiling(scene.soiling);
        const auto report = d_.current_report();
        out->set_report_door_position(report.door_position);
        out->set_report_interrupted(report.interrupted);
        out->set_report_internal_failure(report.internal_failure);
        out->set_report_maintenance(report.maintenance);
        for (const auto e : elements_of(report.elements, d_.elements())) {
          out->add_report_interrupted_elements(e);
        }
        for (const auto e : elements_of(d_.faults().stuck_free, d_.elements())) {
          out->add_stuck_free(e);
        }
        out->set_cycle_ns(ns(d_.cycle()));
        out->set_next_cycle_ns(ns(d_.options().cycle_time()));
        set_line_state(gridscan::description(), d_, c_, to_ns(now), *out);
        return grpc::Status::OK;
      },
      false);
}

grpc::Status GridScanService::SetDoor(grpc::ServerContext*, const v1::SetDoorRequest* in,
                                      v1::Empty*) {
  return on_device(
      in->address(),
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
  return on_device(
      in->address(),
      [&](dp::TimePoint) {
        auto elements = numbers(*in, d_.elements(), "element");
        if (auto* bad = std::get_if<grpc::Status>(&elements)) return *bad;
        // numbers() has checked the range, so the scene takes them all.
        (void)d_.set_interrupted(std::get<std::vector<std::uint16_t>>(elements));
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GridScanService::SetTiming(grpc::ServerContext*, const v1::GridScanTimingRequest* in,
                                        v1::Empty*) {
  return on_device(
      in->address(),
      [&](dp::TimePoint) {
        if (auto why = d_.set_cycle(std::chrono::milliseconds(in->cycle_ms())); !why.empty()) {
          return invalid_argument("cycle_ms", why);
        }
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
  return change(in->address(), [&] { d_.set_soiling(static_cast<std::uint8_t>(in->level())); });
}

grpc::Status GridScanService::fault(const v1::GridScanFaultRequest& in, bool inject) {
  const auto which = in.fault();
  if (which == v1::GRID_SCAN_FAULT_UNSPECIFIED || !v1::GridScanFault_IsValid(which)) {
    return invalid_argument("fault", "a GRID_SCAN_FAULT_* value is required");
  }
  if (inject && which == v1::GRID_SCAN_FAULT_LATE) {
    if (auto bad = check_delay(in.late_ms(), "late_ms"); !bad.ok()) return bad;
  }
  if (which != v1::GRID_SCAN_FAULT_STUCK_FREE && in.elements_size() > 0) {
    return invalid_argument("elements", "only GRID_SCAN_FAULT_STUCK_FREE takes elements");
  }
  if (inject && which == v1::GRID_SCAN_FAULT_STUCK_FREE && in.elements_size() == 0) {
    return invalid_argument("elements", "GRID_SCAN_FAULT_STUCK_FREE needs the elements to stick");
  }
  return on_device(
      in.address(),
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
          case v1::GRID_SCAN_FAULT_LATE:
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

grpc::Status GridScanService::PowerCycle(grpc::ServerContext*, const v1::PowerCycleRequest* in,
                                         v1::Empty*) {
  constexpr std::uint32_t kMaxOffMs = 3'600'000;
  if (in->off_ms() > kMaxOffMs) {
    return invalid_argument("off_ms", std::to_string(in->off_ms()) + " ms outside 0..3600000");
  }
  return on_device(
      in->address(),
      [&](dp::TimePoint now) {
        if (in->off_ms() > 0 && c_.line == nullptr) return needs_simulated_line("GridScan");
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
  return on_device(
      in->address(),
      [&](dp::TimePoint now) {
        in->on() ? d_.power_on(now) : d_.power_off();
        return grpc::Status::OK;
      },
      true);
}

std::unique_ptr<Watcher> gridscan_watcher(std::uint8_t address, const gridscan::Device& d) {
  return std::make_unique<ItemsWatcher>(address, [&d](dp::TimePoint now) {
    const auto leds = d.leds(now);
    const auto report = d.current_report();
    return ItemsWatcher::Items{
        {"power", token_of(d.power())},
        {"mode", token_of(d.mode())},
        {"configuration", token_of(d.configuration())},
        {"led-rx-green", token_of(leds.rx_green)},
        {"led-rx-red", token_of(leds.rx_red)},
        {"led-tx-green", token_of(leds.tx_green)},
        {"door-position", std::to_string(report.door_position)},
        {"interrupted", on_off(report.interrupted)},
        {"internal-failure", on_off(report.internal_failure)},
        {"maintenance", std::to_string(report.maintenance)},
        {"elements", ranges(elements_of(report.elements, d.elements()))},
    };
  });
}

// Its place in the run's list of line devices (rpc/line_devices.h).
LineApi gridscan_line_api() {
  return line_api<GridScanService>(gridscan::description(), v1::GridScan::service_full_name(),
                                   gridscan_watcher);
}

}  // namespace rs4sim::rpc
