// The Faults service (docs/rpc.md "Faults"): bus faults on the simulated bus, the station
// silenced, faults in the RS4's F-input PDUs.
#include "rpc/rs4_services.h"
#include "rpc/service_support.h"
#include "rpc/status.h"

#include <string>

namespace rs4sim::rpc {
namespace {

constexpr std::uint32_t kMaxCount = 1'000'000;
constexpr std::uint32_t kMaxDelayMs = 10'000;

grpc::Status check_count(std::uint32_t count) {
  if (count == 0 || count > kMaxCount) {
    return invalid_argument("count", std::to_string(count) + " outside 1..1000000");
  }
  return grpc::Status::OK;
}

}  // namespace

grpc::Status to_bus_fault(const v1::BusFaultRequest& in, dp::link::Fault& out) {
  switch (in.kind()) {
    case v1::BUS_FAULT_KIND_DROP: out.kind = dp::link::FaultKind::kDrop; break;
    case v1::BUS_FAULT_KIND_CORRUPT: out.kind = dp::link::FaultKind::kCorrupt; break;
    case v1::BUS_FAULT_KIND_DELAY: out.kind = dp::link::FaultKind::kDelay; break;
    default: return invalid_argument("kind", "BUS_FAULT_KIND_DROP, _CORRUPT or _DELAY");
  }
  const auto station = static_cast<std::uint8_t>(in.address());
  switch (in.direction()) {
    case v1::DIRECTION_TO_STATION: out.to = station; break;
    case v1::DIRECTION_FROM_STATION: out.from = station; break;
    default: return invalid_argument("direction", "DIRECTION_TO_STATION or _FROM_STATION");
  }
  if (auto s = check_count(in.count()); !s.ok()) return s;
  out.count = in.count();
  if (out.kind == dp::link::FaultKind::kDelay) {
    if (in.delay_ms() == 0 || in.delay_ms() > kMaxDelayMs) {
      return invalid_argument("delay_ms", std::to_string(in.delay_ms()) + " outside 1..10000");
    }
    out.delay = std::chrono::milliseconds(in.delay_ms());
  }
  out.bit = in.bit();
  return grpc::Status::OK;
}

grpc::Status FaultsService::InjectBusFault(grpc::ServerContext*, const v1::BusFaultRequest* in,
                                           v1::BusFaultResponse* out) {
  dp::link::Fault fault;
  if (auto s = to_bus_fault(*in, fault); !s.ok()) return s;
  return on_device(c_, in->address(), [&](rs4::device::Rs4Device&, dp::TimePoint) {
    auto* bus = c_.target.bus();
    if (bus == nullptr) return needs_simulated_bus();
    out->set_fault_id(bus->inject(fault));
    return grpc::Status::OK;
  });
}

grpc::Status FaultsService::ClearBusFaults(grpc::ServerContext*, const v1::Empty*, v1::Empty*) {
  grpc::Status result;
  c_.executor.run([&] {
    auto* bus = c_.target.bus();
    if (bus == nullptr) {
      result = needs_simulated_bus();
      return;
    }
    bus->clear_faults();
  });
  return result;
}

grpc::Status FaultsService::SetSilenced(grpc::ServerContext*, const v1::SetSilencedRequest* in,
                                        v1::Empty*) {
  return on_device(c_, in->address(), [&](rs4::device::Rs4Device&, dp::TimePoint) {
    auto* bus = c_.target.bus();
    if (bus == nullptr) return needs_simulated_bus();
    bus->set_silenced(static_cast<std::uint8_t>(in->address()), in->silenced());
    return grpc::Status::OK;
  });
}

grpc::Status FaultsService::InjectSafetyFault(grpc::ServerContext*,
                                              const v1::SafetyFaultRequest* in, v1::Empty*) {
  const auto which = in->fault();
  if (which == v1::SAFETY_FAULT_UNSPECIFIED || !v1::SafetyFault_IsValid(which)) {
    return invalid_argument("fault", "a SAFETY_FAULT_* value is required");
  }
  if (which != v1::SAFETY_FAULT_MUTE) {
    if (auto s = check_count(in->count()); !s.ok()) return s;
  }
  return on_device(c_, in->address(), [&](rs4::device::Rs4Device& d, dp::TimePoint) {
    auto& faults = d.adapter().safety_faults();
    switch (which) {
      case v1::SAFETY_FAULT_CORRUPT_CRC2: faults.corrupt_crc2 = in->count(); break;
      case v1::SAFETY_FAULT_REPEAT_NUMBER: faults.repeat_number = in->count(); break;
      case v1::SAFETY_FAULT_SKIP_NUMBER: faults.skip_number = in->count(); break;
      default: faults.mute = in->count() != 0; break;
    }
    return grpc::Status::OK;
  });
}

grpc::Status FaultsService::ClearSafetyFaults(grpc::ServerContext*, const v1::StationRequest* in,
                                              v1::Empty*) {
  return on_device(c_, in->address(), [&](rs4::device::Rs4Device& d, dp::TimePoint) {
    d.adapter().safety_faults() = profisafe::PduFaults{};
    return grpc::Status::OK;
  });
}

grpc::Status FaultsService::AcknowledgeReintegration(grpc::ServerContext*,
                                                     const v1::StationRequest* in, v1::Empty*) {
  return on_device(c_, in->address(), [&](rs4::device::Rs4Device&, dp::TimePoint) {
    const auto why = c_.target.ack_rei(static_cast<std::uint8_t>(in->address()));
    if (why.empty()) return grpc::Status::OK;
    return failed_precondition("STATE", "station " + std::to_string(in->address()), why);
  });
}

}  // namespace rs4sim::rpc
