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
    if (auto e =
            slaves_.set_outputs(master_(), s->spec.address, in->slot(), as_bytes(in->data()))) {
      result = failed_precondition("MASTER", "slave " + std::to_string(s->spec.address),
                                   "the master refused the outputs: " + e.message());
    }
  });
  return result;
}

}  // namespace rs4sim::rpc
