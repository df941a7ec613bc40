// The F-module calls of rs4sim.v1.GsdMaster (rpc/gsd_master_service.h) without a server, for the
// tests of our master as F-host for GSD F-devices: the service runs its work at once on the
// test's thread.
#pragma once

#include "rpc/gsd_master_service.h"

#include <functional>
#include <string>
#include <vector>

namespace rs4sim::app::testing {

class InlineExecutor final : public rpc::Executor {
 public:
  void run(const std::function<void()>& f) override { f(); }
};

struct GsdMasterFCalls {
  rpc::GsdMasterService& api;

  // The first F-module of the slave at `address` as GetSlave shows it.
  v1::GsdMasterFModule f_module(std::uint32_t address) const {
    v1::StationRequest request;
    request.set_address(address);
    v1::GsdMasterSlave slave;
    const auto status = api.GetSlave(nullptr, &request, &slave);
    if (!status.ok() || slave.f_modules_size() == 0) return {};
    return slave.f_modules(0);
  }
  grpc::Status acknowledge(std::uint32_t address, std::uint32_t slot) const {
    v1::GsdFAcknowledgeRequest request;
    request.set_address(address);
    request.set_slot(slot);
    v1::Empty empty;
    return api.AcknowledgeF(nullptr, &request, &empty);
  }
  grpc::Status set_f_outputs(std::uint32_t address, std::uint32_t slot,
                             const std::vector<std::uint8_t>& data) const {
    v1::SetGsdOutputsRequest request;
    request.set_address(address);
    request.set_slot(slot);
    request.set_data(std::string(data.begin(), data.end()));
    v1::Empty empty;
    return api.SetFOutputs(nullptr, &request, &empty);
  }
};

}  // namespace rs4sim::app::testing
