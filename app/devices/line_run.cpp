#include "app/devices/line_run.h"

#include "rpc/rs4_services.h"

#include <utility>

namespace rs4sim::app {

LineRun::LineRun(stream::DeviceKind kind, std::uint8_t address, stream::ByteDevice& core)
    : kind_(kind), address_(address), tap_(core), line_(clock_, tap_) {}

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

ServiceList LineRun::services(const ServiceContext& c, std::unique_ptr<rpc::Watcher> watcher,
                              const MakeService& make) {
  target_ = std::make_unique<rpc::SimulatedLineTarget>(kind_, std::move(watcher), line_);
  tap_.set_hub(target_->events(), address_);
  const rpc::LineContext line{c.executor, clock_, address_, tap_, target_->events(), &line_};
  const rpc::RunContext run{*target_, c.executor};
  ServiceList out{make(line), std::make_shared<rpc::ObservationService>(run),
                  std::make_shared<rpc::SimTimeService>(run)};
  start();
  return out;
}

}  // namespace rs4sim::app
