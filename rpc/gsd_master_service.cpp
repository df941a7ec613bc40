#include "rpc/gsd_master_service.h"

#include "gsd/unit_diag.h"
#include "rpc/gsd_modules.h"
#include "rpc/status.h"

#include <span>
#include <string>

namespace rs4sim::rpc {
namespace {

std::string text_of(std::span<const std::uint8_t> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

void fill_f(const gsd::GsdMasterFModule& f, v1::GsdMasterFModule& out) {
  const auto& h = f.host;
  out.set_slot(static_cast<std::uint32_t>(f.slot));
  out.set_mode(f.mode());
  out.set_f_state(std::string(profisafe::to_token(h.state())));
  out.set_passivated(h.passivated());
  out.set_ack_req(h.ack_req());
  out.set_last_fault(f.last_fault);
  out.set_f_inputs(text_of(h.input()));
  out.set_f_outputs(text_of(f.f_outputs));
  out.set_f_outputs_sent(text_of(f.sent));
  out.set_f_data_length(static_cast<std::uint32_t>(f.f_data_size()));
  out.set_consecutive_number(h.number());
  auto& p = *out.mutable_parameters();
  p.set_f_source_add(f.parameters.source_add);
  p.set_f_dest_add(f.parameters.dest_add);
  p.set_f_wd_time_ms(f.parameters.wd_time_ms);
  p.set_f_par_crc(h.crc1());
  const auto& n = h.counters();
  auto& c = *out.mutable_counters();
  for (const auto& [name, value] : {std::pair{"crc_errors", n.crc_errors},
                                    {"number_errors", n.number_errors},
                                    {"watchdog_timeouts", n.watchdog_timeouts},
                                    {"passivations", n.passivations},
                                    {"reintegrations", n.reintegrations}}) {
    c[name] = value;
  }
}

void fill(const gsd::GsdMasterSlave& s, const dp::master::Master& master, v1::GsdMasterSlave& out) {
  const auto& spec = s.spec;
  out.set_address(spec.address);
  fill_gsd_station(spec, master.inputs(spec.address), s.outputs, out);
  const auto status = master.slave_status(spec.address);
  if (status) {
    out.set_dp_state(dp::master::to_string(status->state));
    out.set_data_exchange(status->state == dp::master::PollState::kDataExchange);
    out.set_data_exchanges(status->counters.data_exchanges);
    if (status->last_error) out.set_last_error(status->last_error.message());
    out.set_diagnosis(text_of({status->last_diag.data(), status->last_diag.size()}));
    for (auto& t :
         gsd::unit_diag_texts(spec.device->unit_diag, gsd::ext_diagnosis(status->last_diag))) {
      out.add_diagnosis_texts(std::move(t));
    }
  }
  out.set_user_prm_data(text_of(spec.setup.user_prm_data));
  out.set_cfg(text_of(spec.setup.cfg));
  for (const auto& f : s.f_modules) fill_f(f, *out.add_f_modules());
}

// The GSD slave at `address`; nullptr and NOT_FOUND (naming this master's GSD slaves) in
// `result` when there is none.
const gsd::GsdMasterSlave* find_slave(const gsd::GsdMasterSlaves& slaves, std::uint32_t address,
                                      grpc::Status& result) {
  const auto* s = address <= 125 ? slaves.find(static_cast<std::uint8_t>(address)) : nullptr;
  if (s == nullptr) {
    result = not_found("no GSD slave at address " + std::to_string(address) +
                       " (this master's GSD slaves: " + slaves.address_list() + ")");
  }
  return s;
}

std::span<const std::uint8_t> as_bytes(const std::string& s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

}  // namespace

grpc::Status GsdMasterService::ListSlaves(grpc::ServerContext*, const v1::Empty*,
                                          v1::ListGsdMasterSlavesResponse* out) {
  executor_.run([&] {
    for (const auto& s : slaves_.slaves()) fill(s, master_(), *out->add_slaves());
  });
  return grpc::Status::OK;
}

grpc::Status GsdMasterService::GetSlave(grpc::ServerContext*, const v1::StationRequest* in,
                                        v1::GsdMasterSlave* out) {
  grpc::Status result;
  executor_.run([&] {
    const auto* s = find_slave(slaves_, in->address(), result);
    if (s == nullptr) return;
    fill(*s, master_(), *out);
  });
  return result;
}

grpc::Status GsdMasterService::SetOutputs(grpc::ServerContext*, const v1::SetGsdOutputsRequest* in,
                                          v1::Empty*) {
  grpc::Status result;
  executor_.run([&] {
    const auto* s = find_slave(slaves_, in->address(), result);
    if (s == nullptr) return;
    const auto& modules = s->spec.modules;
    if (in->slot() >= modules.size()) {
      result = invalid_argument("slot", "slot " + std::to_string(in->slot()) + " outside 0.." +
                                            std::to_string(modules.size() - 1) + " (the slave's " +
                                            std::to_string(modules.size()) + " modules)");
      return;
    }
    const auto& m = modules[in->slot()];
    if (in->data().size() != m.output_len) {
      result =
          invalid_argument("data", std::to_string(in->data().size()) + " bytes; module \"" +
                                       m.name + "\" (slot " + std::to_string(in->slot()) +
                                       ") has " + std::to_string(m.output_len) + " output bytes");
      return;
    }
    if (s->f_module(in->slot()) != nullptr) {
      result = failed_precondition("F_MODULE", "slave " + std::to_string(s->spec.address) +
                                                   " slot " + std::to_string(in->slot()),
                                   "the module is a PROFIsafe F-module: its bytes are our "
                                   "F-host's safety PDU; set its F-data with SetFOutputs");
      return;
    }
    if (auto e =
            slaves_.set_outputs(master_(), s->spec.address, in->slot(), as_bytes(in->data()))) {
      result = failed_precondition("MASTER", "slave " + std::to_string(s->spec.address),
                                   "the master refused the outputs: " + e.message());
    }
  });
  return result;
}

namespace {

// The F-module in `slot` of `s`; nullptr and INVALID_ARGUMENT on `slot` (listing the slave's
// F-modules) when there is none.
const gsd::GsdMasterFModule* find_f_module(const gsd::GsdMasterSlave& s, std::uint32_t slot,
                                           grpc::Status& result) {
  const auto* f = s.f_module(slot);
  if (f == nullptr) {
    result = invalid_argument(
        "slot", "slot " + std::to_string(slot) + " of slave " + std::to_string(s.spec.address) +
                    " is no PROFIsafe F-module with our F-host (its F-modules: slots " +
                    s.f_slot_list() + ")");
  }
  return f;
}

}  // namespace

grpc::Status GsdMasterService::with_f_module(std::uint32_t address, std::uint32_t slot,
                                             const FModuleAct& act) {
  grpc::Status result;
  executor_.run([&] {
    const auto* s = find_slave(slaves_, address, result);
    const auto* f = s == nullptr ? nullptr : find_f_module(*s, slot, result);
    if (f != nullptr) act(*s, *f, result);
  });
  return result;
}

grpc::Status GsdMasterService::SetFOutputs(grpc::ServerContext*,
                                           const v1::SetGsdOutputsRequest* in, v1::Empty*) {
  return with_f_module(in->address(), in->slot(), [&](const auto& s, const auto& f, auto& result) {
    if (in->data().size() != f.f_data_size()) {
      result = invalid_argument(
          "data", std::to_string(in->data().size()) + " bytes; the F-module in slot " +
                      std::to_string(f.slot) + " has " + std::to_string(f.f_data_size()) +
                      " bytes of F-output data");
      return;
    }
    (void)slaves_.set_f_outputs(s.spec.address, f.slot, as_bytes(in->data()));
  });
}

grpc::Status GsdMasterService::AcknowledgeF(grpc::ServerContext*,
                                            const v1::GsdFAcknowledgeRequest* in, v1::Empty*) {
  return with_f_module(in->address(), in->slot(), [&](const auto& s, const auto& f, auto& result) {
    if (!slaves_.acknowledge(s.spec.address, f.slot)) return;
    const std::string state(profisafe::to_token(f.host.state()));
    result = failed_precondition(
        "ACK_REQ", "slave " + std::to_string(s.spec.address) + " slot " + std::to_string(f.slot),
        "no ACK_REQ waits for an acknowledgement: the F-host is in state " + state +
            (state == "ack-required" ? "" : " (ACK_REQ comes once a passivated device "
                                            "communicates without fault again)"));
  });
}

}  // namespace rs4sim::rpc
