#pragma once
// What the rs4sim.v1 service implementations share: run a request on the loop with the
// device of a station, and the common refusals.

#include "rpc/rs4_services.h"

#include <grpcpp/support/status.h>

#include <cstdint>
#include <functional>

namespace rs4sim::rpc {

using DeviceFn = std::function<grpc::Status(rs4::device::Rs4Device&, dp::TimePoint)>;

// Checks the address (INVALID_ARGUMENT), then runs `fn` with the device on the loop
// (NOT_FOUND for an unknown station).
// NOT_FOUND naming the stations there are.
grpc::Status unknown_station(const RunTarget& target, std::uint32_t address);

grpc::Status on_device(const Rs4Context& c, std::uint32_t address, const DeviceFn& fn);
// The same on any run: a run without RS4s answers as unknown_station does.
grpc::Status on_device(const RunContext& c, std::uint32_t address, const DeviceFn& fn);

// FAILED_PRECONDITION: the call needs the manual clock (SimTime) or the simulated bus.
grpc::Status needs_simulated_clock();
grpc::Status needs_simulated_bus();

std::int64_t to_ns(dp::TimePoint t);

// The link fault of a Faults.InjectBusFault request (GsdStations.InjectBusFault too), or the
// INVALID_ARGUMENT naming the field.
grpc::Status to_bus_fault(const v1::BusFaultRequest& in, dp::link::Fault& out);

}  // namespace rs4sim::rpc
