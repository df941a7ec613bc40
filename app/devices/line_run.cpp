#include "app/devices/line_run.h"

#include "rpc/rs4_services.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace rs4sim::app {

const rpc::LineApi& line_api(stream::DeviceKind kind) {
  const auto* api = rpc::find_line_api(kind);
  if (api == nullptr) {
    throw std::logic_error("no line device's service for the kind " +
                           std::string(stream::to_string(kind)) + " (RS4SIM_LINE_DEVICES)");
  }
  return *api;
}

LineRun::LineRun(stream::DeviceKind kind, std::uint8_t address, stream::ByteDevice& core)
    : kind_(kind), address_(address), core_(core), tap_(core), line_(clock_, tap_) {}

void LineRun::start() {
  if (started_) return;
  started_ = true;
  line_.start();
}

void LineRun::run_for(dp::Duration d) {
  start();
  if (target_) {
    (void)target_->run_until([] { return false; }, d);
  } else {
    (void)line_.run_until([] { return false; }, d);
  }
}

ServiceList LineRun::services(const ServiceContext& c) {
  const auto& api = line_api(kind_);
  target_ = std::make_unique<rpc::SimulatedLineTarget>(kind_, api.watcher(address_, core_), line_);
  tap_.set_hub(target_->events(), address_);
  const rpc::LineContext line{c.executor, clock_, address_, tap_, target_->events(), &line_};
  const rpc::RunContext run{*target_, c.executor};
  ServiceList out{api.make(line, core_), std::make_shared<rpc::ObservationService>(run),
                  std::make_shared<rpc::SimTimeService>(run)};
  start();
  return out;
}

}  // namespace rs4sim::app
