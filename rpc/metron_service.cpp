#include "rpc/metron_service.h"

#include "metron/description.h"
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
using line::token_of;
using line::whole_ms;

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

grpc::Status check_metron_address(std::uint32_t address) {
  if (address == metron::kBroadcast) {
    return invalid_argument("address",
                            std::to_string(metron::kBroadcast) +
                                " is the broadcast address [METRON manual \"With node\"]; "
                                "the curtain's is its node (0.." +
                                std::to_string(metron::kMaxNode) + "), or 0 without node mode");
  }
  return grpc::Status::OK;
}

}  // namespace

MetronService::MetronService(LineContext context, metron::Device& device)
    : LineService(context, "METRON", check_metron_address), d_(device) {}

grpc::Status MetronService::GetState(grpc::ServerContext*, const v1::LineDeviceRequest* in,
                                     v1::MetronState* out) {
  return on_device(
      in->address(),
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
        out->set_ossd_function(token_of(d_.slave_state().ossd));
        out->set_first_interrupted(scene.measure(metron::Measurement::kFirstInterrupted));
        out->set_last_interrupted(scene.measure(metron::Measurement::kLastInterrupted));
        out->set_interrupted_count(scene.measure(metron::Measurement::kInterruptedCount));
        out->set_scan_cycle_ms(whole_ms(d_.options().scan_cycle));
        out->set_t_response_ms(whole_ms(d_.options().t_response));
        set_line_state(metron::description(), d_, c_, to_ns(now), *out);
        set_old_delay_ms(*out, out->late_ms());
        return grpc::Status::OK;
      },
      false);
}

grpc::Status MetronService::SetBlocked(grpc::ServerContext*, const v1::SetBlockedRequest* in,
                                       v1::Empty*) {
  return on_device(
      in->address(),
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
  return change(in->address(), [&] { d_.set_synchronised(in->synchronised()); });
}

grpc::Status MetronService::SetInput(grpc::ServerContext*, const v1::SetInputRequest* in,
                                     v1::Empty*) {
  return change(in->address(), [&] { d_.set_input(in->high()); });
}

grpc::Status MetronService::SetTiming(grpc::ServerContext*, const v1::MetronTimingRequest* in,
                                      v1::Empty*) {
  if (auto bad = check_metron_address(in->address()); !bad.ok()) return bad;
  if (in->scan_cycle_ms() < 1 || in->scan_cycle_ms() > 1000) {
    return invalid_argument("scan_cycle_ms",
                            std::to_string(in->scan_cycle_ms()) + " ms outside 1..1000");
  }
  if (in->t_response_ms() < 1 || in->t_response_ms() > 2000) {
    return invalid_argument("t_response_ms",
                            std::to_string(in->t_response_ms()) + " ms outside 1..2000");
  }
  return on_line(
      c_, "METRON", in->address(),
      [&](dp::TimePoint) {
        if (auto why = d_.set_timing(std::chrono::milliseconds(in->scan_cycle_ms()),
                                     std::chrono::milliseconds(in->t_response_ms()));
            !why.empty()) {
          return invalid_argument("scan_cycle_ms", why);
        }
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
        auto f = d_.faults();
        switch (which) {
          case v1::METRON_FAULT_SILENT: f.transmit.silent = inject; break;
          case v1::METRON_FAULT_LATE:
            f.transmit.late =
                inject ? stream::Duration(std::chrono::milliseconds(late_ms)) : stream::Duration{};
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
        d_.set_faults(f);
        return grpc::Status::OK;
      },
      true);
}

std::unique_ptr<Watcher> metron_watcher(std::uint8_t address, const metron::Device& d) {
  return std::make_unique<ItemsWatcher>(address, [&d](dp::TimePoint) {
    return ItemsWatcher::Items{
        {"ossd", on_off(d.ossd_on())},
        {"ossd-function", token_of(d.slave_state().ossd)},
        {"synchronised", on_off(d.scene().synchronised())},
        {"beams", ranges(metron_blocked(d.scene()))},
    };
  });
}

// Its place in the run's list of line devices (rpc/line_devices.h).
LineApi metron_line_api() {
  return line_api<MetronService>(metron::description(), v1::Metron::service_full_name(),
                                 metron_watcher);
}

}  // namespace rs4sim::rpc
