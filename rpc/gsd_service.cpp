#include "rpc/gsd_service.h"

#include "dp/pdu/sap.h"
#include "gsd/unit_diag.h"
#include "rpc/gsd_modules.h"
#include "rpc/items_watcher.h"
#include "rpc/rs4_state.h"
#include "rpc/service_support.h"
#include "rpc/status.h"

#include <array>
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
  for (auto& t : gsd::diagnosis_texts(*spec.device, s.application().diagnosis_blocks())) {
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

grpc::Status check_slot(const gsd::GsdStation& s, std::uint32_t slot) {
  const auto& modules = s.spec().modules;
  if (slot < modules.size()) return grpc::Status::OK;
  return invalid_argument("slot", "slot " + std::to_string(slot) + " outside 0.." +
                                      std::to_string(modules.size() - 1) + " (the station's " +
                                      std::to_string(modules.size()) + " modules)");
}

// "slot 1 (\"PROFIsafe v1.x Module\")", ... or "none".
std::string f_module_list(const gsd::GsdStation& s) {
  std::string out;
  for (const auto& f : s.application().f_modules()) {
    out += (out.empty() ? "slot " : ", slot ") + std::to_string(f.module()) + " (\"" +
           s.spec().modules[f.module()].name + "\")";
  }
  return out.empty() ? "none" : out;
}

// The status and control bits by name [IEC 61784-3-3 safety PDU]; V1 defines activate_FV,
// CE_CRC, WD_timeout and FV_activated only (profisafe/pdu.h).
constexpr std::array<const char*, 8> kControlBits{"iPar_EN", "OA_Req",      "R_cons_nr", "",
                                                  "activate_FV", "Toggle_h", "",          ""};
constexpr std::array<const char*, 8> kStatusBits{"iPar_OK",      "Device_Fault", "CE_CRC",
                                                 "WD_timeout",   "FV_activated", "Toggle_d",
                                                 "cons_nr_R",    ""};
constexpr std::uint8_t kV1ControlBits = profisafe::control_bit::kActivateFv;
constexpr std::uint8_t kV1StatusBits = profisafe::status_bit::kCeCrc |
                                       profisafe::status_bit::kWdTimeout |
                                       profisafe::status_bit::kFvActivated;

void add_bits(std::uint8_t byte, std::uint8_t defined, const std::array<const char*, 8>& names,
              google::protobuf::RepeatedPtrField<std::string>& out) {
  for (unsigned bit = 0; bit < 8; ++bit) {
    if (((byte & defined) >> bit & 1U) != 0 && *names[bit] != '\0') out.Add(names[bit]);
  }
}

std::string as_string(std::span<const std::uint8_t> b) { return {b.begin(), b.end()}; }

// Our master's F-host (gsd::GsdMasterFModule): `sent` is 0 while it sends fail-safe values.
void fill_f_host(const gsd::GsdMasterFModule& f, v1::GsdFHostView& out) {
  const profisafe::FHost& h = f.host;
  const auto& c = h.counters();
  out.set_state(std::string(profisafe::to_token(h.state())));
  out.set_f_inputs(as_string(h.input()));
  out.set_f_outputs(as_string(f.sent));
  out.set_last_fault(f.last_fault);
  out.set_last_status(h.last_status());
  out.set_crc_errors(c.crc_errors);
  out.set_number_errors(c.number_errors);
  out.set_watchdog_timeouts(c.watchdog_timeouts);
  out.set_device_ce_crc(c.device_ce_crc);
  out.set_device_wd_timeout(c.device_wd_timeout);
  out.set_passivations(c.passivations);
  out.set_reintegrations(c.reintegrations);
}

void fill_f_module(const gsd::GsdStation& s, const gsd::FModuleDevice& f,
                   const gsd::GsdMasterSlaves* hosts, v1::GsdFModule& out) {
  const profisafe::FDevice& d = f.device();
  const bool v2 = d.version() == profisafe::ProtocolVersion::kV2;
  out.set_slot(static_cast<std::uint32_t>(f.module()));
  out.set_name(s.spec().modules[f.module()].name);
  out.set_mode(std::string(gsd::f_mode_token(d)));
  out.set_state(std::string(gsd::f_state_token(d)));
  out.set_diagnosis(d.diagnosis());
  if (d.diagnosis() != 0) {
    out.set_diagnosis_text(gsd::f_diagnosis_text(s.spec().device->unit_diag, d.diagnosis()));
  }
  out.set_f_dest_add(f.dest_add());
  out.set_consecutive_number(d.last_number());
  out.set_host_control(f.host_control());
  add_bits(f.host_control(), v2 ? 0xFF : kV1ControlBits, kControlBits,
           *out.mutable_host_control_bits());
  out.set_status(d.status_byte());
  add_bits(d.status_byte(), v2 ? 0xFF : kV1StatusBits, kStatusBits, *out.mutable_status_bits());
  out.set_f_inputs(as_string(f.f_inputs()));
  out.set_f_outputs(as_string(f.f_outputs()));
  out.set_f_outputs_fail_safe(!d.sends_process_values());
  out.set_f_data_length(static_cast<std::uint32_t>(f.f_data_size()));
  out.set_f_wd_time_ms(f.wd_time_ms());
  const auto& c = d.counters();
  out.set_pdus(c.pdus);
  out.set_crc_errors(c.crc_errors);
  out.set_number_errors(c.number_errors);
  out.set_watchdog_timeouts(c.watchdog_timeouts);
  const auto& faults = d.faults();
  out.set_pending_corrupt_crc2(faults.corrupt_crc2);
  out.set_pending_wrong_number(faults.skip_number);
  out.set_pending_repeat_number(faults.repeat_number);
  out.set_held_ms(static_cast<std::uint64_t>(f.hold().count()));
  const gsd::GsdMasterSlave* slave = hosts != nullptr ? hosts->find(s.address()) : nullptr;
  const gsd::GsdMasterFModule* host = slave != nullptr ? slave->f_module(f.module()) : nullptr;
  if (host != nullptr) fill_f_host(*host, *out.mutable_host());
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
        if (auto bad = check_slot(s, in->slot()); !bad.ok()) return bad;
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

grpc::Status GsdStationsService::on_f_module(std::uint32_t address, std::uint32_t slot,
                                             const FModuleFn& fn) {
  return on_station(
      address,
      [&](gsd::GsdStation& s) {
        if (auto bad = check_slot(s, slot); !bad.ok()) return bad;
        gsd::FModuleDevice* f = s.application().f_module(slot);
        if (f == nullptr) {
          return invalid_argument("slot", "module \"" + s.spec().modules[slot].name + "\" (slot " +
                                              std::to_string(slot) +
                                              ") is no PROFIsafe F-module; the station's "
                                              "F-modules: " +
                                              f_module_list(s));
        }
        return fn(s, *f);
      },
      true);
}

grpc::Status GsdStationsService::on_f_host(std::uint32_t address, std::uint32_t slot,
                                           const FHostFn& fn) {
  return on_f_module(address, slot, [&](gsd::GsdStation& s, gsd::FModuleDevice& f) {
    const gsd::GsdMasterSlave* slave = c_.f_hosts != nullptr ? c_.f_hosts->find(s.address())
                                                             : nullptr;
    const gsd::GsdMasterFModule* h = slave != nullptr ? slave->f_module(f.module()) : nullptr;
    if (h == nullptr) {
      return failed_precondition("LINK", "F-host",
                                 "this run's master is not ours on the simulated bus: our "
                                 "F-host runs with --link memory");
    }
    return fn(s, f, *h);
  });
}

grpc::Status GsdStationsService::GetFModules(grpc::ServerContext*, const v1::StationRequest* in,
                                             v1::GsdFModules* out) {
  return with_station(in->address(), false, [&](gsd::GsdStation& s) {
    out->set_address(s.address());
    for (const auto& f : s.application().f_modules()) {
      fill_f_module(s, f, c_.f_hosts, *out->add_modules());
    }
  });
}

grpc::Status GsdStationsService::SetFInputs(grpc::ServerContext*,
                                            const v1::SetGsdInputsRequest* in, v1::Empty*) {
  return on_f_module(in->address(), in->slot(), [&](gsd::GsdStation& s, gsd::FModuleDevice& f) {
    if (in->data().size() != f.f_data_size()) {
      return invalid_argument("data", std::to_string(in->data().size()) + " bytes; F-module \"" +
                                          s.spec().modules[f.module()].name + "\" (slot " +
                                          std::to_string(f.module()) + ") has " +
                                          std::to_string(f.f_data_size()) + " F-input bytes");
    }
    f.set_f_inputs(as_bytes(in->data()));
    return grpc::Status::OK;
  });
}

namespace {

grpc::Status check_f_fault(const v1::InjectGsdFFaultRequest& in) {
  switch (in.fault()) {
    case v1::GSD_F_FAULT_CORRUPT_CRC2:
    case v1::GSD_F_FAULT_WRONG_NUMBER:
    case v1::GSD_F_FAULT_REPEAT_NUMBER:
      if (in.count() < 1 || in.count() > 1000000) {
        return invalid_argument("count", std::to_string(in.count()) + " outside 1..1000000");
      }
      return grpc::Status::OK;
    case v1::GSD_F_FAULT_DELAY:
      if (in.delay_ms() < 1 || in.delay_ms() > 600000) {
        return invalid_argument("delay_ms", std::to_string(in.delay_ms()) + " outside 1..600000");
      }
      return grpc::Status::OK;
    case v1::GSD_F_FAULT_WRONG_F_DEST_ADD:
      // 0 and 65535 are no valid F_Dest_Add [IEC 61784-3-3 F-Parameters]
      if (in.f_dest_add() < 1 || in.f_dest_add() > 65534) {
        return invalid_argument("f_dest_add", std::to_string(in.f_dest_add()) +
                                                  " outside 1..65534");
      }
      return grpc::Status::OK;
    default:
      return invalid_argument("fault", "fault kind " + std::to_string(in.fault()) +
                                           " unknown: a GSD_F_FAULT_* value is required");
  }
}

}  // namespace

grpc::Status GsdStationsService::InjectFFault(grpc::ServerContext*,
                                              const v1::InjectGsdFFaultRequest* in, v1::Empty*) {
  if (auto bad = check_f_fault(*in); !bad.ok()) return bad;
  return on_f_module(in->address(), in->slot(), [&](gsd::GsdStation& s, gsd::FModuleDevice& f) {
    auto& faults = f.device().faults();
    switch (in->fault()) {
      case v1::GSD_F_FAULT_CORRUPT_CRC2: faults.corrupt_crc2 += in->count(); break;
      case v1::GSD_F_FAULT_WRONG_NUMBER: faults.skip_number += in->count(); break;
      case v1::GSD_F_FAULT_REPEAT_NUMBER: faults.repeat_number += in->count(); break;
      case v1::GSD_F_FAULT_DELAY: f.hold_answers(std::chrono::milliseconds(in->delay_ms())); break;
      default:
        if (in->f_dest_add() == f.dest_add()) {
          return invalid_argument("f_dest_add", std::to_string(in->f_dest_add()) +
                                                    " is the device's own F_Dest_Add already");
        }
        (void)s.set_f_dest_add(f.module(), static_cast<std::uint16_t>(in->f_dest_add()));
    }
    return grpc::Status::OK;
  });
}

grpc::Status GsdStationsService::ClearFFaults(grpc::ServerContext*,
                                              const v1::GsdFModuleRequest* in, v1::Empty*) {
  return on_f_module(in->address(), in->slot(), [&](gsd::GsdStation& s, gsd::FModuleDevice& f) {
    f.device().faults() = profisafe::PduFaults{};
    f.hold_answers(std::chrono::milliseconds(0));
    const std::uint16_t own = gsd::configured_f_dest_add(s.spec(), f.module());
    if (own != f.dest_add()) (void)s.set_f_dest_add(f.module(), own);
    return grpc::Status::OK;
  });
}

grpc::Status GsdStationsService::SetFOutputs(grpc::ServerContext*,
                                             const v1::SetGsdOutputsRequest* in, v1::Empty*) {
  const auto data = as_bytes(in->data());
  return on_f_host(in->address(), in->slot(),
                   [&](gsd::GsdStation& s, gsd::FModuleDevice& f, const gsd::GsdMasterFModule&) {
                     if (!c_.f_hosts->set_f_outputs(s.address(), f.module(), data)) {
                       return grpc::Status::OK;
                     }
                     return invalid_argument(
                         "data", std::to_string(data.size()) + " bytes; F-module \"" +
                                     s.spec().modules[f.module()].name + "\" (slot " +
                                     std::to_string(f.module()) + ") has " +
                                     std::to_string(f.f_data_size()) + " F-output bytes");
                   });
}

grpc::Status GsdStationsService::AckFHost(grpc::ServerContext*, const v1::GsdFModuleRequest* in,
                                          v1::Empty*) {
  return on_f_host(in->address(), in->slot(),
                   [&](gsd::GsdStation& s, gsd::FModuleDevice& f, const gsd::GsdMasterFModule& h) {
                     if (c_.f_hosts->acknowledge(s.address(), f.module())) {
                       return failed_precondition(
                           "STATE", "F-host",
                           "no ACK_REQ to acknowledge: the F-host is \"" +
                               std::string(profisafe::to_token(h.host.state())) + "\"");
                     }
                     return grpc::Status::OK;
                   });
}

namespace {

// "fdevice-state", or "fdevice-state:1" on a station with two F-modules or more.
std::string f_item(const gsd::GsdStation& station, const gsd::FModuleDevice& f, const char* what) {
  return station.application().f_modules().size() > 1
             ? std::string(what) + ":" + std::to_string(f.module())
             : std::string(what);
}

void add_f_items(const gsd::GsdStation& station, ItemsWatcher::Items& items) {
  for (const auto& f : station.application().f_modules()) {
    const auto& d = f.device();
    const std::string diagnosis =
        d.diagnosis() == 0 ? std::string()
                           : std::to_string(d.diagnosis()) + ": " +
                                 gsd::f_diagnosis_text(station.spec().device->unit_diag,
                                                       d.diagnosis());
    items.emplace_back(f_item(station, f, "fdevice-state"), std::string(gsd::f_state_token(d)));
    items.emplace_back(f_item(station, f, "fdevice-diagnosis"), diagnosis);
    items.emplace_back(f_item(station, f, "f-inputs"), gsd::io_hex(f.f_inputs()));
    items.emplace_back(f_item(station, f, "f-outputs"), gsd::io_hex(f.f_outputs()));
  }
}

}  // namespace

std::unique_ptr<Watcher> gsd_watcher(const gsd::GsdStation& station) {
  return std::make_unique<ItemsWatcher>(station.address(), [&station](dp::TimePoint) {
    const auto& a = station.application();
    ItemsWatcher::Items items{
        {"dp-state", dp::slave::to_string(station.slave().state())},
        {"online", station.online() ? "yes" : "no"},
        {"inputs", gsd::io_hex(a.inputs())},
        {"outputs", gsd::io_hex(a.outputs())},
        {"ext-diag", a.ext_diag() ? "on" : "off"},
        {"diagnosis", gsd::io_hex(a.diagnosis_blocks())},
        {"diagnosis-text", gsd::diagnosis_text(*station.spec().device, a.diagnosis_blocks())}};
    add_f_items(station, items);
    return items;
  });
}

std::unique_ptr<Watcher> gsd_fhost_watcher(const gsd::GsdStation& station,
                                           const gsd::GsdMasterSlaves& hosts) {
  return std::make_unique<ItemsWatcher>(station.address(), [&station, &hosts](dp::TimePoint) {
    ItemsWatcher::Items items;
    const gsd::GsdMasterSlave* slave = hosts.find(station.address());
    for (const auto& f : station.application().f_modules()) {
      const gsd::GsdMasterFModule* h = slave != nullptr ? slave->f_module(f.module()) : nullptr;
      if (h == nullptr) continue;
      items.emplace_back(f_item(station, f, "fhost-state"),
                         std::string(profisafe::to_token(h->host.state())));
    }
    return items;
  });
}

}  // namespace rs4sim::rpc
