// User-facing API of the class 1 master (master.h).

#include "dp/master/master.h"
#include "dp/master/master_error.h"

namespace rs4sim::dp::master {

std::error_code Master::set_outputs(std::uint8_t slave, std::span<const std::uint8_t> outputs) {
  SlaveHandler* s = find(slave);
  if (s == nullptr) return make_error_code(MasterError::kUnknownSlave);
  return s->set_outputs(outputs);
}

std::span<const std::uint8_t> Master::inputs(std::uint8_t slave) const {
  const SlaveHandler* s = find(slave);
  return s == nullptr ? std::span<const std::uint8_t>{} : s->inputs();
}

std::optional<SlaveStatus> Master::slave_status(std::uint8_t slave) const {
  const SlaveHandler* s = find(slave);
  if (s == nullptr) return std::nullopt;
  return s->status();
}

std::optional<PollState> Master::poll_state(std::uint8_t slave) const {
  const SlaveHandler* s = find(slave);
  if (s == nullptr) return std::nullopt;
  return s->state();
}

std::vector<std::uint8_t> Master::slave_addresses() const {
  std::vector<std::uint8_t> out;
  out.reserve(slaves_.size());
  for (const SlaveHandler& s : slaves_) out.push_back(s.address());
  return out;
}

std::error_code Master::global_control(const pdu::GlobalControl& gc) {
  static constexpr std::size_t kQueueLimit = 8;
  if (gc.reserved != 0) return make_error_code(MasterError::kBadArgument);  // bits 0, 6, 7
  if (gc_queue_.size() >= kQueueLimit) return make_error_code(MasterError::kQueueFull);
  gc_queue_.push_back(gc);
  return {};
}

void Master::set_operating_mode(OperatingMode mode) {
  if (mode == mode_) return;
  mode_ = mode;
  pdu::GlobalControl gc;  // [IEC 61158-6-3 Global_Control]: Clear `02 00`, Operate `00 00`
  gc.clear_data = mode == OperatingMode::kClear;
  (void)global_control(gc);
}

boost::outcome_v2::std_result<Dpv1RequestId> Master::submit(std::uint8_t slave, Dpv1Job job) {
  SlaveHandler* s = find(slave);
  if (s == nullptr) return make_error_code(MasterError::kUnknownSlave);
  job.id = next_id_;
  if (auto ec = s->submit(std::move(job))) return ec;
  const Dpv1RequestId id = next_id_;
  next_id_ = next_id_ == UINT32_MAX ? 1 : next_id_ + 1;
  return id;
}

boost::outcome_v2::std_result<Dpv1RequestId> Master::read(std::uint8_t slave, std::uint8_t slot,
                                                          std::uint8_t index, std::uint8_t length) {
  Dpv1Job job;
  job.operation = Dpv1Operation::kRead;
  job.slot = slot;
  job.index = index;
  job.length = length;
  return submit(slave, std::move(job));
}

boost::outcome_v2::std_result<Dpv1RequestId> Master::write(std::uint8_t slave, std::uint8_t slot,
                                                           std::uint8_t index,
                                                           std::span<const std::uint8_t> data) {
  if (data.empty() || data.size() > pdu::kDpv1MaxData) {
    return make_error_code(MasterError::kBadArgument);
  }
  Dpv1Job job;
  job.operation = Dpv1Operation::kWrite;
  job.slot = slot;
  job.index = index;
  job.data.assign(data.begin(), data.end());
  return submit(slave, std::move(job));
}

std::error_code Master::acknowledge_alarm(std::uint8_t slave, std::uint8_t slot,
                                          std::uint8_t alarm_type, std::uint8_t seq_nr) {
  SlaveHandler* s = find(slave);
  if (s == nullptr) return make_error_code(MasterError::kUnknownSlave);
  return s->acknowledge_alarm(slot, alarm_type, seq_nr);
}

std::vector<MasterEvent> Master::take_events() {
  std::vector<MasterEvent> out;
  events_.take(out);
  return out;
}

void dispatch(const MasterEvent& e, MasterObserver& o) {
  struct Visitor {
    MasterObserver& o;
    void operator()(const SlaveEnteredDataExchange& v) const { o.on_entered_data_exchange(v); }
    void operator()(const SlaveLeftDataExchange& v) const { o.on_left_data_exchange(v); }
    void operator()(const SlaveFault& v) const { o.on_slave_fault(v); }
    void operator()(const DiagReceived& v) const { o.on_diag(v); }
    void operator()(const AlarmReceived& v) const { o.on_alarm(v); }
    void operator()(const AlarmAcknowledged& v) const { o.on_alarm_acknowledged(v); }
    void operator()(const Dpv1Result& v) const { o.on_dpv1_result(v); }
    void operator()(const CycleCompleted& v) const { o.on_cycle(v); }
  };
  std::visit(Visitor{o}, e);
}

}  // namespace rs4sim::dp::master
