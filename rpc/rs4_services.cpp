#include "rpc/rs4_services.h"

#include "rpc/diagnosis_service.h"
#include "rpc/plc_service.h"
#include "rpc/rs4_state.h"
#include "rpc/service_support.h"
#include "rpc/status.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/param_doc/parameter_document.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <variant>

namespace rs4sim::rpc {
namespace {

using rs4::device::Rs4Device;
namespace scanner = rs4::scanner;

constexpr std::uint64_t kMaxSimulatedMs = 24ULL * 3600 * 1000;  // one call advances ≤ 24 h
constexpr std::uint32_t kMaxPressMs = 60'000;

// Simulated time runs in slices of at most this much loop time: between two slices the loop
// serves the other calls, the live view and the event stream, and a call whose client has
// gone (cancelled, deadline exceeded) stops at the next slice. A 24 h Advance of a big bus
// takes minutes of CPU; in one piece it would hold the loop for all of them.
constexpr auto kSlice = std::chrono::milliseconds(20);

// `done` for one slice: true once `holds()` does or the slice's loop time is used up
// (`sliced`); the clock is read every 64 checks (a check runs after every bus event).
class SliceDone {
 public:
  explicit SliceDone(const std::function<bool()>& holds)
      : holds_(holds), end_(std::chrono::steady_clock::now() + kSlice) {}
  bool operator()() {
    if (sliced_) return true;
    if (holds_()) return true;
    if ((++checks_ & 63U) == 0 && std::chrono::steady_clock::now() >= end_) sliced_ = true;
    return sliced_;
  }
  [[nodiscard]] bool sliced() const { return sliced_; }

 private:
  const std::function<bool()>& holds_;
  std::chrono::steady_clock::time_point end_;
  std::uint32_t checks_ = 0;
  bool sliced_ = false;
};

grpc::Status stopped_by_client(std::int64_t now_ns) {
  return grpc::Status(
      grpc::StatusCode::CANCELLED,
      "the client cancelled; simulated time stopped at now_ns " + std::to_string(now_ns));
}

scanner::Point point(const v1::PointMm& p) { return {p.x(), p.y()}; }

// The shape of the request, or the INVALID_ARGUMENT naming the field.
std::variant<scanner::Shape, grpc::Status> to_shape(const v1::AddObstacleRequest& in) {
  using v1::AddObstacleRequest;
  switch (in.shape_case()) {
    case AddObstacleRequest::kCircle:
      return scanner::Shape{scanner::Circle{point(in.circle().centre()), in.circle().radius()}};
    case AddObstacleRequest::kPolygon: {
      scanner::Polygon polygon;
      for (const auto& v : in.polygon().vertices()) polygon.vertices.push_back(point(v));
      return scanner::Shape{std::move(polygon)};
    }
    case AddObstacleRequest::kWall:
      return scanner::Shape{scanner::Wall{point(in.wall().a()), point(in.wall().b())}};
    case AddObstacleRequest::kPoint:
      return scanner::Shape{scanner::PointObstacle{point(in.point())}};
    case AddObstacleRequest::kContour: {
      const auto& mm = in.contour().mm();
      if (static_cast<std::size_t>(mm.size()) != scanner::kSegmentCount) {
        return invalid_argument("contour.mm", std::to_string(mm.size()) + " values, the RS4 has " +
                                                  std::to_string(scanner::kSegmentCount) +
                                                  " segments");
      }
      scanner::RawContour raw;
      for (int i = 0; i < mm.size(); ++i) {
        if (mm[i] > 0xFFFF) {
          return invalid_argument("contour.mm[" + std::to_string(i) + "]",
                                  std::to_string(mm[i]) + " mm is above 65535");
        }
        raw.mm.push_back(static_cast<std::uint16_t>(mm[i]));
      }
      return scanner::Shape{std::move(raw)};
    }
    case AddObstacleRequest::SHAPE_NOT_SET: break;
  }
  return invalid_argument("shape", "one of circle, polygon, wall, point or contour is required");
}

std::optional<scanner::Fault> to_fault(v1::Fault f) {
  switch (f) {
    case v1::FAULT_OSSD_CROSS_CIRCUIT: return scanner::Fault::kOssdCrossCircuit;
    case v1::FAULT_MOTOR_SPEED: return scanner::Fault::kMotorSpeed;
    case v1::FAULT_INTERNAL_HARDWARE: return scanner::Fault::kInternalHardware;
    case v1::FAULT_DAZZLED: return scanner::Fault::kDazzled;
    default: return std::nullopt;
  }
}

}  // namespace

grpc::Status DeviceService::ListDevices(grpc::ServerContext*, const v1::ListDevicesRequest*,
                                        v1::ListDevicesResponse* out) {
  c_.executor.run([&] {
    for (const auto a : c_.target.addresses()) {
      auto* d = out->add_devices();
      d->set_address(a);
      d->set_kind("rs4");
      const auto* device = c_.target.device(a);
      d->set_powered(device != nullptr && device->powered());
    }
  });
  return grpc::Status::OK;
}

grpc::Status DeviceService::AddObstacle(grpc::ServerContext*, const v1::AddObstacleRequest* in,
                                        v1::AddObstacleResponse* out) {
  auto shape = to_shape(*in);
  if (auto* bad = std::get_if<grpc::Status>(&shape)) return *bad;
  if (auto ok = scanner::check_shape(std::get<scanner::Shape>(shape)); !ok) {
    return invalid_argument(std::string(scanner::to_token(std::get<scanner::Shape>(shape))),
                            ok.error().message());
  }
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    auto id = d.scanner().edit_scene(now).add(std::move(std::get<scanner::Shape>(shape)));
    if (!id) {
      return failed_precondition("SCENE", "station " + std::to_string(in->address()),
                                 id.error().message());
    }
    out->set_obstacle_id(id.value());
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::RemoveObstacle(grpc::ServerContext*,
                                           const v1::RemoveObstacleRequest* in, v1::Empty*) {
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    if (!d.scanner().edit_scene(now).remove(in->obstacle_id())) {
      return not_found("no obstacle " + std::to_string(in->obstacle_id()) + " at station " +
                       std::to_string(in->address()));
    }
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::ClearScene(grpc::ServerContext*, const v1::StationRequest* in,
                                       v1::Empty*) {
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    d.scanner().edit_scene(now).clear();
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::ViolateField(grpc::ServerContext*, const v1::ViolateFieldRequest* in,
                                         v1::AddObstacleResponse* out) {
  if (in->field() != v1::FIELD_KIND_PROTECTIVE && in->field() != v1::FIELD_KIND_WARNING) {
    return invalid_argument("field", "FIELD_KIND_PROTECTIVE or FIELD_KIND_WARNING");
  }
  const bool warning = in->field() == v1::FIELD_KIND_WARNING;
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    const std::uint8_t pair = d.scanner().status().first_pair;
    const std::string subject = "station " + std::to_string(in->address());
    if (pair < 1 || pair > scanner::kFieldPairCount) {
      return failed_precondition("STATE", subject, "no field pair is active (RS4 not measuring)");
    }
    auto raw = scanner::field_violation(d.scanner().parameters().pairs[pair - 1U], warning);
    if (!raw) {
      return failed_precondition(
          "PARAMETERS", subject,
          "field pair " + std::to_string(pair) + " has no " +
              (warning ? "warning field beyond its protective field" : "protective field"));
    }
    auto id = d.scanner().edit_scene(now).add(std::move(*raw));
    if (!id) return failed_precondition("SCENE", subject, id.error().message());
    out->set_obstacle_id(id.value());
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::SetContamination(grpc::ServerContext*,
                                             const v1::SetContaminationRequest* in, v1::Empty*) {
  if (in->percent() > 100) {
    return invalid_argument("percent", std::to_string(in->percent()) + " is above 100");
  }
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    d.scanner().set_contamination(static_cast<std::uint8_t>(in->percent()), now);
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::fault(std::uint32_t address, v1::Fault which, bool inject) {
  const auto f = to_fault(which);
  if (!f) {
    return invalid_argument("fault",
                            "one of FAULT_OSSD_CROSS_CIRCUIT, FAULT_MOTOR_SPEED, "
                            "FAULT_INTERNAL_HARDWARE, FAULT_DAZZLED");
  }
  return on_device(c_, address, [&](Rs4Device& d, dp::TimePoint now) {
    auto r = inject ? d.scanner().inject_fault(*f, now) : d.scanner().clear_fault(*f, now);
    if (!r) {
      return failed_precondition("FAULT", "station " + std::to_string(address),
                                 r.error().message());
    }
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::InjectFault(grpc::ServerContext*, const v1::FaultRequest* in,
                                        v1::Empty*) {
  return fault(in->address(), in->fault(), true);
}

grpc::Status DeviceService::ClearFault(grpc::ServerContext*, const v1::FaultRequest* in,
                                       v1::Empty*) {
  return fault(in->address(), in->fault(), false);
}

grpc::Status DeviceService::SetPcAdapter(grpc::ServerContext*, const v1::SetPcAdapterRequest* in,
                                         v1::Empty*) {
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    c_.target.set_pc_adapter(d, in->attached(), now);
    return grpc::Status::OK;
  });
}

// The button on X1 [RS4 manual §4.3]. PressRestart holds it and releases it after duration_ms;
// SetRestartButton holds or releases it until told otherwise and supersedes a pulse still running
// (each change of the button gets a number; a pulse releases only if it was the last change).
grpc::Status DeviceService::PressRestart(grpc::ServerContext*, const v1::PressRestartRequest* in,
                                         v1::Empty*) {
  if (in->duration_ms() == 0 || in->duration_ms() > kMaxPressMs) {
    return invalid_argument("duration_ms", std::to_string(in->duration_ms()) +
                                               " ms outside 1..60000 (the RS4 accepts 120..5000)");
  }
  const auto address = static_cast<std::uint8_t>(in->address());
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    if (d.adapter().restart_button()) {
      return failed_precondition("BUTTON", "station " + std::to_string(in->address()),
                                 "the restart button is already held; release it first "
                                 "(SetRestartButton pressed = false) or wait for the press to end");
    }
    d.adapter().set_restart_button(true, now);
    const std::uint64_t press = ++(*button_changes_)[address];
    Rs4Target& target = c_.target;
    target.after(std::chrono::milliseconds(in->duration_ms()),
                 [&target, address, press, changes = button_changes_] {
                   if ((*changes)[address] != press) return;  // superseded by SetRestartButton
                   if (auto* device = target.device(address)) {
                     device->adapter().set_restart_button(false, target.now());
                   }
                 });
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::SetRestartButton(grpc::ServerContext*,
                                             const v1::SetRestartButtonRequest* in, v1::Empty*) {
  const auto address = static_cast<std::uint8_t>(in->address());
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    ++(*button_changes_)[address];
    d.adapter().set_restart_button(in->pressed(), now);
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::SetPower(grpc::ServerContext*, const v1::SetPowerRequest* in,
                                     v1::Empty*) {
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    if (in->on() && !d.powered()) d.power_on(now);
    if (!in->on() && d.powered()) d.power_off(now);
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::PowerCycle(grpc::ServerContext*, const v1::StationRequest* in,
                                       v1::Empty*) {
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    d.power_cycle(now);
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::SetAddressSwitches(grpc::ServerContext*,
                                               const v1::SetAddressSwitchesRequest* in,
                                               v1::Empty*) {
  if (in->high() > 0xF) return invalid_argument("high", "HexH switch takes 0..15");
  if (in->low() > 0xF) return invalid_argument("low", "HexL switch takes 0..15");
  const rs4::adapter::AddressSwitches s{static_cast<std::uint8_t>(in->high()),
                                        static_cast<std::uint8_t>(in->low())};
  if (auto a = rs4::adapter::station_address(s); !a) {
    return invalid_argument("high", a.error().message());
  }
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint) {
    d.set_address_switches(s);
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::ExchangeScanner(grpc::ServerContext*,
                                            const v1::ExchangeScannerRequest* in, v1::Empty*) {
  if (in->serial_number() == 0) {
    return invalid_argument("serial_number", "0 is no serial number (1..4294967295)");
  }
  for (const auto a : c_.target.addresses()) {
    const auto* other = c_.target.device(a);
    if (a != in->address() && other != nullptr &&
        other->scanner().parameters().identity.serial_number == in->serial_number()) {
      return invalid_argument("serial_number", "the RS4 at station " + std::to_string(a) +
                                                   " has serial number " +
                                                   std::to_string(in->serial_number()));
    }
  }
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    if (!d.exchange_unit(in->serial_number(), now)) {
      return failed_precondition("EXCHANGE", "station " + std::to_string(in->address()),
                                 "the RS4 could not be exchanged");
    }
    return grpc::Status::OK;
  });
}

namespace {

void fill_document(const Rs4Device& d, v1::ParameterSetDocument& out) {
  const auto& set = d.scanner().parameters();
  out.set_json(rs4::param_doc::to_document(set));
  out.set_transfer_crc32(d.scanner().transfer_checksum());
  out.set_serial_number(set.identity.serial_number);
}

}  // namespace

grpc::Status DeviceService::GetParameterSet(grpc::ServerContext*, const v1::StationRequest* in,
                                            v1::ParameterSetDocument* out) {
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint) {
    fill_document(d, *out);
    return grpc::Status::OK;
  });
}

grpc::Status DeviceService::SetParameterSet(grpc::ServerContext*,
                                            const v1::SetParameterSetRequest* in,
                                            v1::ParameterSetDocument* out) {
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    const std::string station = "station " + std::to_string(in->address());
    auto& rs4 = d.scanner();
    const auto doc = rs4::param_doc::from_document(in->json(), rs4.parameters(),
                                                   {in->allow_partial_field()});
    if (!doc) {
      return invalid_argument("json", doc.issue.message());
    }
    if (!d.powered()) return failed_precondition("POWER", station, "the RS4 is powered off");
    // Through the optical PC adapter [RS4 manual §7.2]; one the user attached stays on.
    const bool attached_here = !d.adapter().view().pc_adapter_attached;
    if (attached_here) c_.target.set_pc_adapter(d, true, now);
    const auto detach = [&] {
      if (attached_here) c_.target.set_pc_adapter(d, false, now);
    };
    if (!d.adapter().rs232_switched_through()) {
      detach();
      return failed_precondition("PC_ADAPTER", station,
                                 "the RS232 is not switched through (a proxy sync is running, "
                                 "[RS4 manual §5.1.1] bit 3)");
    }
    if (auto r = rs4.enter_configuration(now); !r) {
      detach();
      return failed_precondition("CONFIGURATION", station, r.error().message());
    }
    const auto written = rs4.set_parameters(*doc.set, now);
    (void)rs4.leave_configuration(now);
    detach();
    if (!written) return failed_precondition("CONFIGURATION", station, written.error().message());
    fill_document(d, *out);
    return grpc::Status::OK;
  });
}

grpc::Status ObservationService::GetState(grpc::ServerContext*, const v1::StationRequest* in,
                                          v1::DeviceState* out) {
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint now) {
    fill_state(d, static_cast<std::uint8_t>(in->address()), now, *out);
    Rs4Target& rs4s = *c_.target.rs4s();  // a device was found: the run has RS4s
    if (!rs4s.plc_view(static_cast<std::uint8_t>(in->address()), *out->mutable_plc())) {
      out->clear_plc();
    }
    if (!rs4s.link_timing(static_cast<std::uint8_t>(in->address()), *out->mutable_link_timing())) {
      out->clear_link_timing();
    }
    return grpc::Status::OK;
  });
}

grpc::Status ObservationService::GetContour(grpc::ServerContext*, const v1::StationRequest* in,
                                            v1::Contour* out) {
  return on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint) {
    fill_contour(d, *out);
    return grpc::Status::OK;
  });
}

void SimTimeService::time(v1::TimeResponse& out) const {
  out.set_now_ns(to_ns(c_.target.now()));
  out.set_simulated(c_.target.simulated());
  out.set_start_ns(to_ns(start_));
}

grpc::Status SimTimeService::Now(grpc::ServerContext*, const v1::Empty*, v1::TimeResponse* out) {
  c_.executor.run([&] { time(*out); });
  return grpc::Status::OK;
}

grpc::Status SimTimeService::Advance(grpc::ServerContext* context, const v1::AdvanceRequest* in,
                                     v1::TimeResponse* out) {
  if (in->duration_ms() == 0 || in->duration_ms() > kMaxSimulatedMs) {
    return invalid_argument("duration_ms",
                            std::to_string(in->duration_ms()) + " ms outside 1..86400000 (24 h)");
  }
  grpc::Status result;
  std::optional<dp::TimePoint> end;  // simulated
  const std::function<bool()> never = [] { return false; };
  for (bool more = true; more;) {
    c_.executor.run([&] {
      more = false;
      if (!c_.target.simulated()) {
        result = needs_simulated_clock();
        return;
      }
      if (!end) end = c_.target.now() + std::chrono::milliseconds(in->duration_ms());
      SliceDone slice(never);
      c_.target.run_until(std::ref(slice), *end - c_.target.now());
      more = slice.sliced() && c_.target.now() < *end;
      time(*out);
    });
    if (more && context->IsCancelled()) return stopped_by_client(out->now_ns());
  }
  return result;
}

namespace {

bool on_plc_side(v1::Condition condition) {
  return condition == v1::CONDITION_PLC_OSSD_ON || condition == v1::CONDITION_PLC_OSSD_OFF ||
         condition == v1::CONDITION_PLC_PASSIVATED || condition == v1::CONDITION_PLC_ACK_REQUIRED;
}

// A PLC-side condition on what the F-host hands the PLC program (PlcView): the input byte as
// read (fail-safe 0 while passivated [IEC 61784-3-3 passivation]) and the F-host's state.
bool plc_holds(Rs4Target& rs4s, std::uint8_t address, v1::Condition condition) {
  v1::PlcView plc;
  if (!rs4s.plc_view(address, plc)) return false;
  switch (condition) {
    case v1::CONDITION_PLC_OSSD_ON: return plc.input().ossd();
    case v1::CONDITION_PLC_OSSD_OFF: return !plc.input().ossd();
    case v1::CONDITION_PLC_PASSIVATED:
      return plc.fhost_state() == "passivated" || plc.fhost_state() == "ack-required";
    case v1::CONDITION_PLC_ACK_REQUIRED: return plc.fhost_state() == "ack-required";
    default: return false;
  }
}

// The scanner-side conditions: what the RS4 itself sends and does.
bool device_holds(Rs4Device& d, v1::Condition condition) {
  const std::uint8_t in_byte = d.adapter().input_byte();
  switch (condition) {
    case v1::CONDITION_DATA_EXCHANGE: return d.adapter().view().connected;
    case v1::CONDITION_OSSD_ON: return (in_byte & rs4::adapter::kInputOssd) != 0;
    case v1::CONDITION_OSSD_OFF: return (in_byte & rs4::adapter::kInputOssd) == 0;
    case v1::CONDITION_PROXY_REQUEST: return (in_byte & rs4::adapter::kInputProxyRequest) != 0;
    case v1::CONDITION_RS4_MEASURING:
      return d.scanner().status().state == scanner::ScannerState::kMeasuring;
    default: return false;
  }
}

}  // namespace

grpc::Status SimTimeService::RunUntil(grpc::ServerContext* context, const v1::RunUntilRequest* in,
                                      v1::RunUntilResponse* out) {
  if (in->timeout_ms() == 0 || in->timeout_ms() > kMaxSimulatedMs) {
    return invalid_argument("timeout_ms",
                            std::to_string(in->timeout_ms()) + " ms outside 1..86400000 (24 h)");
  }
  const auto condition = in->condition();
  if (condition == v1::CONDITION_UNSPECIFIED || !v1::Condition_IsValid(condition)) {
    return invalid_argument("condition", "a CONDITION_* value is required");
  }
  const auto address = static_cast<std::uint8_t>(in->address());
  std::optional<dp::TimePoint> end;  // simulated: where the timeout ends
  for (;;) {
    bool more = false;
    const grpc::Status s = on_device(c_, in->address(), [&](Rs4Device& d, dp::TimePoint) {
      if (!c_.target.simulated()) return needs_simulated_clock();
      Rs4Target& rs4s = *c_.target.rs4s();
      v1::PlcView plc;
      if (on_plc_side(condition) && !rs4s.plc_view(address, plc)) {
        return failed_precondition("PLC", "station " + std::to_string(address),
                                   "this run has no PLC side (no F-host of ours on the link): "
                                   "the PLC_* conditions need the simulated bus");
      }
      const std::function<bool()> holds = [&d, &rs4s, address, condition] {
        return on_plc_side(condition) ? plc_holds(rs4s, address, condition)
                                      : device_holds(d, condition);
      };
      if (!end) end = c_.target.now() + std::chrono::milliseconds(in->timeout_ms());
      bool reached = holds();
      if (!reached) {
        SliceDone slice(holds);
        c_.target.run_until(std::ref(slice), *end - c_.target.now());
        reached = holds();
        more = !reached && slice.sliced() && c_.target.now() < *end;
      }
      out->set_reached(reached);
      out->set_now_ns(to_ns(c_.target.now()));
      return grpc::Status::OK;
    });
    if (!s.ok() || !more) return s;
    if (context->IsCancelled()) return stopped_by_client(out->now_ns());
  }
}

std::vector<std::shared_ptr<grpc::Service>> rs4_service_set(
    Rs4Target& target, Executor& executor, const std::vector<gsd::GsdStation*>& gsd) {
  const Rs4Context c{target, executor};
  std::vector<std::shared_ptr<grpc::Service>> set{
      std::make_shared<DeviceService>(c), std::make_shared<ObservationService>(c),
      std::make_shared<FaultsService>(c), std::make_shared<SimTimeService>(c),
      std::make_shared<DiagnosticsService>(c, gsd)};
  // rs4sim.v1.Plc where the run is the PLC (the simulated segment).
  if (PlcTarget* plc = target.plc()) set.push_back(std::make_shared<PlcService>(*plc, executor));
  return set;
}

}  // namespace rs4sim::rpc
