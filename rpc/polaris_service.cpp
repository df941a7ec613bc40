#include "rpc/polaris_service.h"

#include "modbus/rtu_frame.h"
#include "polaris/description.h"
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
using line::numbers;
using line::on_line;
using line::on_off;
using line::ranges;
using line::set_line_state;

grpc::Status check_modbus_address(std::uint32_t address) {
  if (!modbus::is_slave_address(address)) {
    return invalid_argument("address", std::to_string(address) + " outside " +
                                           std::to_string(modbus::kMinSlaveAddress) + ".." +
                                           std::to_string(modbus::kMaxSlaveAddress) +
                                           ", the Modbus slave addresses "
                                           "[Modbus serial line V1.02 §2.2]");
  }
  return grpc::Status::OK;
}

}  // namespace

PolarisService::PolarisService(LineContext context, polaris::Device& device)
    : LineService(context, "Polaris", check_modbus_address), d_(device) {}

grpc::Status PolarisService::GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                                      v1::PolarisState* out) {
  return on_device(
      in->address(),
      [&](dp::TimePoint now) {
        const auto& o = d_.options();
        out->set_address(c_.address);
        out->set_family(std::string(polaris::to_string(o.family)));
        out->set_beams(o.beams);
        out->set_data_mode(std::string(polaris::to_string(o.mode)));
        out->set_role(std::string(polaris::to_token(o.role)));
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
        out->set_calibrating(d_.calibrating(now));
        if (const auto end = d_.calibration_end()) out->set_calibration_end_ns(to_ns(*end));
        out->set_calibrations(d_.calibrations());
        out->set_direction(std::string(polaris::to_token(o.direction)));
        out->set_detection(std::string(polaris::to_token(o.detection)));
        out->set_pn2_filter(o.pn2_filter);
        out->set_scan_time_ms(static_cast<std::uint32_t>(o.scan_time.count()));
        out->set_bit_order(std::string(polaris::to_token(o.bit_order)));
        out->set_nak_on_error(o.nak_on_error);
        const polaris::Leds leds = d_.leds(now);
        out->set_tx_led(std::string(polaris::to_token(leds.tx)));
        out->set_rx_led(std::string(polaris::to_token(leds.rx)));
        out->set_manual_adjustment(d_.manual_adjustment());
        out->set_calibrations_failed(d_.calibrations_failed());
        out->set_storage(std::string(polaris::to_token(o.storage)));
        out->set_storage_mode(std::string(polaris::to_token(o.storage_mode)));
        out->set_scan_ns(std::chrono::duration_cast<std::chrono::nanoseconds>(d_.scan()).count());
        out->set_response_column(static_cast<std::uint32_t>(o.response_column));
        set_line_state(polaris::description(), d_, c_, to_ns(now), *out);
        return grpc::Status::OK;
      },
      false);
}

grpc::Status PolarisService::SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                                        v1::Empty*) {
  return on_device(
      in->address(),
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

grpc::Status PolarisService::Calibrate(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                                       v1::Empty*) {
  return on_device(
      in->address(),
      [&](dp::TimePoint now) { return calibration_refused(d_.start_calibration(now)); }, true);
}

grpc::Status PolarisService::calibration_refused(const std::error_code& ec) const {
  if (!ec) return grpc::Status::OK;
  const std::string subject = "Polaris " + std::to_string(c_.address);
  if (ec == polaris::ConfigError::kBeamsInterrupted) {
    return failed_precondition("BEAMS_INTERRUPTED", subject,
                               "beams are interrupted: auto-calibration needs a free detection "
                               "area [Polaris manual §7.2]");
  }
  const auto end = d_.calibration_end();
  return failed_precondition("CALIBRATING", subject,
                             "an auto-calibration runs until " +
                                 std::to_string(end ? to_ns(*end) : 0) + " ns (0.4 s per beam)");
}

grpc::Status PolarisService::SetTiming(grpc::ServerContext*, const v1::PolarisTimingRequest* in,
                                       v1::Empty*) {
  if (auto bad = check_modbus_address(in->address()); !bad.ok()) return bad;
  if (in->response_time_us() > 1'000'000) {
    return invalid_argument("response_time_us", std::to_string(in->response_time_us()) +
                                                    " outside 0..1000000 (0: the model's)");
  }
  if (in->response_column() > 2) {
    return invalid_argument("response_column",
                            std::to_string(in->response_column()) +
                                ": the model tables have columns 1 and 2 [Polaris manual §2.1]");
  }
  return on_line(
      c_, "Polaris", in->address(),
      [&](dp::TimePoint now) {
        const auto column = in->response_column() == 2 ? polaris::ResponseColumn::kSecond
                                                       : polaris::ResponseColumn::kFirst;
        if (const auto ec = d_.set_response_time(std::chrono::microseconds(in->response_time_us()),
                                                 column, now)) {
          return invalid_argument("response_time_us", ec.message());
        }
        return grpc::Status::OK;
      },
      true);
}

grpc::Status PolarisService::SetSw1(grpc::ServerContext*, const v1::PolarisSw1Request* in,
                                    v1::Empty*) {
  return on_device(
      in->address(),
      [&](dp::TimePoint now) { return calibration_refused(d_.set_sw1(in->closed(), now)); }, true);
}

std::unique_ptr<Watcher> polaris_watcher(std::uint8_t address, const polaris::Device& d) {
  return std::make_unique<ItemsWatcher>(address, [&d](dp::TimePoint now) {
    return ItemsWatcher::Items{
        {"pn1", on_off(d.pn1())},
        {"pn2", on_off(d.pn2(now))},
        {"beams", ranges(d.interrupted())},
        {"calibrating", on_off(d.calibrating(now))},
    };
  });
}

// Its place in the run's list of line devices (rpc/line_devices.h).
LineApi polaris_line_api() {
  return line_api<PolarisService>(polaris::description(), v1::Polaris::service_full_name(),
                                  polaris_watcher);
}

}  // namespace rs4sim::rpc
