#include "rpc/plc_service.h"

#include "rpc/status.h"
#include "rs4/adapter/cyclic_bytes.h"

#include <string>

namespace rs4sim::rpc {
namespace {

namespace adapter = rs4::adapter;

constexpr std::uint32_t kMaxPulseMs = 60000;

std::string station_list(const std::vector<std::uint8_t>& stations) {
  std::string out;
  for (const auto a : stations) out += (out.empty() ? "" : ", ") + std::to_string(a);
  return out.empty() ? "none" : out;
}

void fill(const PlcTarget& target, std::uint8_t address, v1::PlcOutputs& out) {
  const std::uint8_t byte = target.output_byte(address).value_or(0);
  out.set_address(address);
  out.set_output_byte(byte);
  out.mutable_output()->set_field_pair(static_cast<std::uint32_t>(byte & adapter::kOutputFieldPair));
  out.mutable_output()->set_restart((byte & adapter::kOutputRestart) != 0);
  out.mutable_output()->set_proxy_enable((byte & adapter::kOutputProxyEnable) != 0);
  out.set_manual_acknowledge(target.manual_acknowledge(address));
}

}  // namespace

std::uint8_t with_outputs(std::uint8_t byte, const v1::SetPlcOutputsRequest& in) {
  const auto bit = [&byte](std::uint8_t mask, bool on) {
    byte = static_cast<std::uint8_t>(on ? byte | mask : byte & ~mask);
  };
  if (in.has_field_pair()) {
    byte = static_cast<std::uint8_t>(static_cast<unsigned>(byte & ~adapter::kOutputFieldPair) |
                                     in.field_pair());
  }
  if (in.has_restart()) bit(adapter::kOutputRestart, in.restart());
  if (in.has_proxy_enable()) bit(adapter::kOutputProxyEnable, in.proxy_enable());
  return byte;
}

grpc::Status PlcService::on_station(std::uint32_t address, v1::PlcOutputs& out,
                                    const StationFn& fn) {
  grpc::Status result;
  executor_.run([&] {
    const auto station = static_cast<std::uint8_t>(address);
    if (address > 255 || !target_.output_byte(station)) {
      result = not_found("no PLC output byte of ours for station " + std::to_string(address) +
                         " (this run's PLC side writes to: " +
                         station_list(target_.plc_stations()) + ")");
      return;
    }
    result = fn(station);
    if (result.ok()) fill(target_, station, out);
  });
  return result;
}

grpc::Status PlcService::SetOutputs(grpc::ServerContext*, const v1::SetPlcOutputsRequest* in,
                                    v1::PlcOutputs* out) {
  if (in->has_field_pair() && in->field_pair() > adapter::kOutputFieldPair) {
    return invalid_argument("field_pair", std::to_string(in->field_pair()) +
                                              " does not fit bits 2..0 (0..7)");
  }
  return on_station(in->address(), *out, [&](std::uint8_t station) {
    if (in->has_restart()) ++(*restart_changes_)[station];
    target_.set_output_byte(station, with_outputs(*target_.output_byte(station), *in));
    return grpc::Status::OK;
  });
}

grpc::Status PlcService::PulseRestart(grpc::ServerContext*, const v1::PulseRestartRequest* in,
                                      v1::PlcOutputs* out) {
  if (in->duration_ms() == 0 || in->duration_ms() > kMaxPulseMs) {
    return invalid_argument("duration_ms", std::to_string(in->duration_ms()) +
                                               " ms outside 1..60000 (the RS4 takes 120..5000)");
  }
  return on_station(in->address(), *out, [&](std::uint8_t station) {
    const std::uint8_t byte = *target_.output_byte(station);
    if ((byte & adapter::kOutputRestart) != 0) {
      return failed_precondition("RESTART", "station " + std::to_string(station),
                                 "the restart bit is already 1; set it 0 first (SetOutputs)");
    }
    target_.set_output_byte(station, static_cast<std::uint8_t>(byte | adapter::kOutputRestart));
    const std::uint64_t pulse = ++(*restart_changes_)[station];
    PlcTarget& target = target_;
    target_.after(std::chrono::milliseconds(in->duration_ms()),
                  [&target, station, pulse, changes = restart_changes_] {
                    if ((*changes)[station] != pulse) return;  // SetOutputs changed it since
                    const auto now = target.output_byte(station);
                    if (now) {
                      target.set_output_byte(
                          station, static_cast<std::uint8_t>(*now & ~adapter::kOutputRestart));
                    }
                  });
    return grpc::Status::OK;
  });
}

grpc::Status PlcService::SetAcknowledgeMode(grpc::ServerContext*,
                                            const v1::SetAcknowledgeModeRequest* in,
                                            v1::PlcOutputs* out) {
  return on_station(in->address(), *out, [&](std::uint8_t station) {
    target_.set_manual_acknowledge(station, in->manual());
    return grpc::Status::OK;
  });
}

}  // namespace rs4sim::rpc
