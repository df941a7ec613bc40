#include "app/demos/demo_proxy.h"

#include "app/runtime/author.h"
#include "app/runtime/master_proxy.h"
#include "rs4/adapter/cyclic_bytes.h"

#include <variant>

namespace rs4sim::app {
namespace {

// The demo's RS4 and its proxy start new in every run, so the demo keeps the Proxy-FB's
// retentive record in memory only (`persist` off); `rs4sim master` keeps it in the archive.
// Its versions are dated by the wall clock at each write, the simulated time beside it, and
// record the OS user and this computer, as `rs4sim master`'s without --user.
proxy::SchedulerConfig scheduler_config() {
  proxy::Recording recording;
  recording.author = local_author("");
  return proxy::SchedulerConfig{"demo", 1, wall_now, true, false, recording};
}

}  // namespace

DemoProxy::DemoProxy(rs4::device::Rs4Segment& segment, storage::ParameterArchive& archive)
    : segment_(segment),
      scheduler_(archive, scheduler_config()),
      driver_(scheduler_, *this),
      sync_(scheduler_.add(segment.rs4_address())) {
  segment_.set_observer([this](const dp::master::MasterEvent& e) { on_event(e); });
}

DemoProxy::~DemoProxy() { segment_.set_observer({}); }

const proxy::FbOutputs& DemoProxy::outputs() const { return sync_.outputs(); }

const storage::StationKey& DemoProxy::station() const { return sync_.station(); }

void DemoProxy::on_event(const dp::master::MasterEvent& e) {
  const auto now = segment_.now();
  if (const auto* r = std::get_if<dp::master::Dpv1Result>(&e)) {
    const auto it = pending_.find(r->id);
    if (it == pending_.end()) return;  // somebody else's DPV1 request
    const std::uint8_t address = it->second;
    pending_.erase(it);
    driver_.on_record_result(address, to_record_result(*r), now);
    if (on_progress_) on_progress_(sync_.progress());
  } else if (std::holds_alternative<dp::master::CycleCompleted>(e)) {
    on_cycle(now);
  }
}

void DemoProxy::on_cycle(dp::TimePoint now) {
  for (const auto address : std::exchange(refused_, {})) {
    driver_.on_record_result(address, proxy::RecordResult::no_response(), now);
  }
  // The demo's PLC gives the FB the Proxy-Enable it sends the RS4 (output bit 6,
  // [RS4 manual §5.1.2]), as a PLC program would.
  const std::uint8_t address = segment_.rs4_address();
  driver_.set_proxy_enable(address,
                           (segment_.output_byte() & rs4::adapter::kOutputProxyEnable) != 0);
  driver_.on_input_byte(address, segment_.input_byte());
  driver_.poll(now);
  const bool running = sync_.active();
  if (!running && running_) ++ended_;
  running_ = running;
}

bool DemoProxy::wait_sync(const RunUntil& run_until, dp::Duration timeout,
                          const OnProgress& on_progress) {
  const std::size_t ended_before = ended_;
  on_progress_ = on_progress;
  struct Clear {
    OnProgress& f;
    ~Clear() { f = {}; }
  } clear{on_progress_};
  return run_until([&] { return ended_ > ended_before; }, timeout);
}

void DemoProxy::submit_write(std::uint8_t address, std::span<const std::uint8_t> record) {
  submitted(address, segment_.master().write(address, 0, 2, record));
}

void DemoProxy::submit_read(std::uint8_t address, std::uint8_t length) {
  submitted(address, segment_.master().read(address, 0, 2, length));
}

void DemoProxy::submitted(std::uint8_t address,
                          const boost::outcome_v2::std_result<dp::master::Dpv1RequestId>& id) {
  if (!running_) {  // the first record of a new sync
    records_ = 0;
    running_ = true;
  }
  ++records_;
  if (id) {
    pending_[id.value()] = address;
  } else {
    refused_.push_back(address);  // e.g. not in data exchange: a failed record next cycle
  }
}

}  // namespace rs4sim::app
