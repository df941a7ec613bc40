#include "rpc/gsd_service.h"

#include "dp/pdu/sap.h"
#include "gsd/unit_diag.h"
#include "rpc/gsd_modules.h"
#include "rpc/items_watcher.h"
#include "rpc/rs4_state.h"
#include "rpc/service_support.h"
#include "rpc/status.h"

#include <string>

namespace rs4sim::rpc {
namespace {

std::string station_list(const std::vector<gsd::GsdStation*>& stations) {
  std::string s;
  for (const auto* st : stations) s += (s.empty() ? "" : ", ") + std::to_string(st->address());
  return s.empty() ? "none" : s;
}

struct AlarmKind {
  v1::GsdAlarmType type;
  const char* name;     // as in GsdStation.alarms
  const char* keyword;  // the GSD's [PROFIBUS GSD spec DPV1 keywords]
  bool gsd::Dpv1Info::*declared;
};
constexpr AlarmKind kAlarms[] = {
    {v1::GSD_ALARM_TYPE_DIAGNOSTIC, "diagnostic", "Diagnostic_Alarm_supp",
     &gsd::Dpv1Info::diagnostic_alarm},
    {v1::GSD_ALARM_TYPE_PROCESS, "process", "Process_Alarm_supp", &gsd::Dpv1Info::process_alarm},
    {v1::GSD_ALARM_TYPE_PULL, "pull", "Pull_Plug_Alarm_supp", &gsd::Dpv1Info::pull_plug_alarm},
    {v1::GSD_ALARM_TYPE_PLUG, "plug", "Pull_Plug_Alarm_supp", &gsd::Dpv1Info::pull_plug_alarm},
    {v1::GSD_ALARM_TYPE_STATUS, "status", "Status_Alarm_supp", &gsd::Dpv1Info::status_alarm},
    {v1::GSD_ALARM_TYPE_UPDATE, "update", "Update_Alarm_supp", &gsd::Dpv1Info::update_alarm},
};

void fill(const gsd::GsdStation& s, const GsdServiceContext& c, v1::GsdStation& out) {
  const auto& spec = s.spec();
  out.set_address(s.address());
  fill_gsd_station(spec, s.application().inputs(), s.application().outputs(), out);
  out.set_dp_state(dp::slave::to_string(s.slave().state()));
  out.set_online(s.online());
  out.set_data_exchanges(s.application().exchanges());
  out.set_prm_fault(s.application().prm_fault());
  for (auto& t : gsd::unit_diag_texts(spec.device->unit_diag, s.application().diagnosis_blocks())) {
    out.add_diagnosis_texts(std::move(t));
  }
  out.set_dpv1(spec.device->dpv1.slave);
  if (spec.device->dpv1.slave) {
    for (const auto& a : kAlarms) {
      if (spec.device->dpv1.*a.declared) out.add_alarms(a.name);
    }
  }
  const dp::link::TurnaroundStats* timing = c.turnaround ? c.turnaround(s.address()) : nullptr;
  if (timing != nullptr) fill_link_timing(*timing, c.slot_time_us, *out.mutable_link_timing());
}

std::span<const std::uint8_t> as_bytes(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

grpc::Status check_address(std::uint32_t address) {
  if (address > dp::pdu::sap::kMaxStationAddress) {
    return invalid_argument("address", "station address " + std::to_string(address) +
                                           " outside 0.." +
                                           std::to_string(dp::pdu::sap::kMaxStationAddress));
  }
  return grpc::Status::OK;
}

}  // namespace

grpc::Status GsdStationsService::on_station(std::uint32_t address, const StationFn& fn,
                                            bool changes) {
  if (auto bad = check_address(address); !bad.ok()) return bad;
  grpc::Status result;
  c_.executor.run([&] {
    for (auto* s : c_.stations) {
      if (s->address() != address) continue;
      result = fn(*s);
      if (changes && c_.changed) c_.changed();
      return;
    }
    result = not_found("no GSD station at address " + std::to_string(address) +
                       " (this run's GSD stations: " + station_list(c_.stations) + ")");
  });
  return result;
}

grpc::Status GsdStationsService::with_station(std::uint32_t address, bool changes,
                                              const std::function<void(gsd::GsdStation&)>& fn) {
  return on_station(
      address,
      [&](gsd::GsdStation& s) {
        fn(s);
        return grpc::Status::OK;
      },
      changes);
}

grpc::Status GsdStationsService::ListStations(grpc::ServerContext*, const v1::Empty*,
                                              v1::ListGsdStationsResponse* out) {
  c_.executor.run([&] {
    for (const auto* s : c_.stations) fill(*s, c_, *out->add_stations());
  });
  return grpc::Status::OK;
}

grpc::Status GsdStationsService::GetStation(grpc::ServerContext*, const v1::StationRequest* in,
                                            v1::GsdStation* out) {
  return with_station(in->address(), false, [&](gsd::GsdStation& s) { fill(s, c_, *out); });
}

grpc::Status GsdStationsService::SetInputs(grpc::ServerContext*, const v1::SetGsdInputsRequest* in,
                                           v1::Empty*) {
  return on_station(
      in->address(),
      [&](gsd::GsdStation& s) {
        const auto& modules = s.spec().modules;
        if (in->slot() >= modules.size()) {
          return invalid_argument("slot", "slot " + std::to_string(in->slot()) + " outside 0.." +
                                              std::to_string(modules.size() - 1) +
                                              " (the station's " + std::to_string(modules.size()) +
                                              " modules)");
        }
        const auto& m = modules[in->slot()];
        if (in->data().size() != m.input_len) {
          return invalid_argument("data", std::to_string(in->data().size()) + " bytes; module \"" +
                                              m.name + "\" (slot " + std::to_string(in->slot()) +
                                              ") has " + std::to_string(m.input_len) +
                                              " input bytes");
        }
        (void)s.application().set_inputs(in->slot(), as_bytes(in->data()));
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GsdStationsService::SetDiagnosis(grpc::ServerContext*,
                                              const v1::SetGsdDiagnosisRequest* in, v1::Empty*) {
  return on_station(
      in->address(),
      [&](gsd::GsdStation& s) {
        // The 6 standard bytes count towards Max_Diag_Data_Len ([PROFIBUS GSD spec]).
        const std::size_t max = s.spec().device->max_diag_data_len;
        if (6 + in->blocks().size() > max) {
          return invalid_argument("blocks", std::to_string(in->blocks().size()) +
                                                " bytes; the GSD's Max_Diag_Data_Len " +
                                                std::to_string(max) + " leaves " +
                                                std::to_string(max > 6 ? max - 6 : 0) +
                                                " bytes after the 6 standard ones");
        }
        if (auto e = s.application().set_diagnosis(as_bytes(in->blocks()), in->ext_diag())) {
          return invalid_argument("blocks", "refused by the slave: " + e.message());
        }
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GsdStationsService::RaiseAlarm(grpc::ServerContext*,
                                            const v1::RaiseGsdAlarmRequest* in, v1::Empty*) {
  const AlarmKind* kind = nullptr;
  for (const auto& a : kAlarms) {
    if (a.type == in->type()) kind = &a;
  }
  if (kind == nullptr) return invalid_argument("type", "a GSD_ALARM_TYPE_* value is required");
  if (in->slot() > 254) {
    return invalid_argument("slot", std::to_string(in->slot()) + " outside 0..254");
  }
  return on_station(
      in->address(),
      [&](gsd::GsdStation& s) {
        const auto& d = *s.spec().device;
        const std::string subject = "station " + std::to_string(s.address());
        if (!d.dpv1.slave) {
          return failed_precondition("GSD", subject,
                                     s.spec().file +
                                         " does not declare DPV1_Slave = 1: "
                                         "a DP-V0 slave has no alarms");
        }
        if (!(d.dpv1.*kind->declared)) {
          return failed_precondition("GSD", subject,
                                     s.spec().file + " does not declare " + kind->keyword +
                                         " = 1: no " + kind->name + " alarm");
        }
        if (auto e = s.application().raise_alarm(static_cast<std::uint8_t>(kind->type),
                                                 static_cast<std::uint8_t>(in->slot()),
                                                 as_bytes(in->user_data()))) {
          return failed_precondition("STATE", subject,
                                     "the slave cannot send it now: " + e.message() + " (state " +
                                         dp::slave::to_string(s.slave().state()) + ")");
        }
        return grpc::Status::OK;
      },
      true);
}

grpc::Status GsdStationsService::SetOnline(grpc::ServerContext*, const v1::SetGsdOnlineRequest* in,
                                           v1::Empty*) {
  return with_station(in->address(), true, [&](gsd::GsdStation& s) { s.set_online(in->online()); });
}

grpc::Status GsdStationsService::InjectBusFault(grpc::ServerContext*, const v1::BusFaultRequest* in,
                                                v1::BusFaultResponse* out) {
  dp::link::Fault fault;
  if (auto bad = to_bus_fault(*in, fault); !bad.ok()) return bad;
  return on_station(
      in->address(),
      [&](gsd::GsdStation&) {
        if (c_.bus == nullptr) return needs_simulated_bus();
        out->set_fault_id(c_.bus->inject(fault));
        return grpc::Status::OK;
      },
      false);
}

grpc::Status GsdStationsService::ClearBusFaults(grpc::ServerContext*, const v1::Empty*,
                                                v1::Empty*) {
  grpc::Status result;
  c_.executor.run([&] {
    if (c_.bus == nullptr) {
      result = needs_simulated_bus();
      return;
    }
    c_.bus->clear_faults();
  });
  return result;
}

std::unique_ptr<Watcher> gsd_watcher(const gsd::GsdStation& station) {
  return std::make_unique<ItemsWatcher>(station.address(), [&station](dp::TimePoint) {
    const auto& a = station.application();
    return ItemsWatcher::Items{
        {"dp-state", dp::slave::to_string(station.slave().state())},
        {"online", station.online() ? "yes" : "no"},
        {"inputs", gsd::io_hex(a.inputs())},
        {"outputs", gsd::io_hex(a.outputs())},
        {"ext-diag", a.ext_diag() ? "on" : "off"},
        {"diagnosis", gsd::io_hex(a.diagnosis_blocks())},
        {"diagnosis-text", gsd::diagnosis_text(*station.spec().device, a.diagnosis_blocks())}};
  });
}

}  // namespace rs4sim::rpc
