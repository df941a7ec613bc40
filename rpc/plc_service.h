#pragma once
// rs4sim.v1.Plc (plc.proto, docs/rpc.md "The PLC's outputs"): the process output byte the PLC
// program writes [RS4 manual §5.1.2] (field pair, restart, Proxy-Enable) and its F-host's
// acknowledgement mode [RS4 manual §7.3.2], on the runs where rs4sim is the PLC: the simulated
// segment of `run --link memory` and `rs4sim master`. Each call runs on the loop through the
// Executor; PlcTarget is what the run gives it.

#include "dp/time/clock.h"
#include "rpc/executor.h"
#include "rs4sim/v1/plc.grpc.pb.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace rs4sim::rpc {

class PlcTarget {
 public:
  virtual ~PlcTarget() = default;
  // The stations whose output byte we write.
  [[nodiscard]] virtual std::vector<std::uint8_t> plc_stations() const = 0;
  // The byte handed to the F-host now; nullopt: not one of plc_stations().
  [[nodiscard]] virtual std::optional<std::uint8_t> output_byte(std::uint8_t address) const = 0;
  // From the next cycle on; only for one of plc_stations().
  virtual void set_output_byte(std::uint8_t address, std::uint8_t out) = 0;
  [[nodiscard]] virtual bool manual_acknowledge(std::uint8_t address) const = 0;
  virtual void set_manual_acknowledge(std::uint8_t address, bool manual) = 0;
  // Runs `f` on the loop after `delay` (simulated runs: runs the clock through it first).
  virtual void after(dp::Duration delay, std::function<void()> f) = 0;

 protected:
  PlcTarget() = default;
  PlcTarget(const PlcTarget&) = default;
  PlcTarget& operator=(const PlcTarget&) = default;
};

// The output byte with the request's bits over it (the others kept) [RS4 manual §5.1.2].
std::uint8_t with_outputs(std::uint8_t byte, const v1::SetPlcOutputsRequest& in);

class PlcService final : public v1::Plc::Service {
 public:
  // `target` outlives the service.
  PlcService(PlcTarget& target, Executor& executor) : target_(target), executor_(executor) {}
  grpc::Status SetOutputs(grpc::ServerContext*, const v1::SetPlcOutputsRequest* in,
                          v1::PlcOutputs* out) override;
  grpc::Status PulseRestart(grpc::ServerContext*, const v1::PulseRestartRequest* in,
                            v1::PlcOutputs* out) override;
  grpc::Status SetAcknowledgeMode(grpc::ServerContext*, const v1::SetAcknowledgeModeRequest* in,
                                  v1::PlcOutputs* out) override;

 private:
  using StationFn = std::function<grpc::Status(std::uint8_t address)>;
  // `fn` on the loop for a station of ours, then its outputs into `out`; NOT_FOUND otherwise.
  grpc::Status on_station(std::uint32_t address, v1::PlcOutputs& out, const StationFn& fn);

  PlcTarget& target_;
  Executor& executor_;
  // Each change of a station's restart bit gets a number: a pulse clears the bit only if it
  // made the last change (SetOutputs in between wins).
  std::shared_ptr<std::map<std::uint8_t, std::uint64_t>> restart_changes_ =
      std::make_shared<std::map<std::uint8_t, std::uint64_t>>();
};

}  // namespace rs4sim::rpc
