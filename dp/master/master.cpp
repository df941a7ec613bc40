#include "dp/master/master.h"

#include "dp/master/master_error.h"
#include "dp/pdu/sap.h"

#include <algorithm>
#include <system_error>

namespace rs4sim::dp::master {
namespace {

MasterConfig checked(MasterConfig c) {
  if (auto ec = validate(c)) throw std::system_error(ec, "dp::master::Master configuration");
  return c;
}

}  // namespace

Master::Master(MasterConfig config)
    : config_(checked(std::move(config))),
      phase_(config_.claim_token ? MasterPhase::kListening : MasterPhase::kRunning) {
  index_.fill(-1);
  slaves_.reserve(config_.slaves.size());
  for (const SlaveEntry& s : config_.slaves) {
    index_[s.address] = static_cast<std::int16_t>(slaves_.size());
    slaves_.emplace_back(s, config_.fdl_status_first);
  }
}

SlaveHandler* Master::find(std::uint8_t address) {
  if (address >= index_.size() || index_[address] < 0) return nullptr;
  return &slaves_[static_cast<std::size_t>(index_[address])];
}

const SlaveHandler* Master::find(std::uint8_t address) const {
  if (address >= index_.size() || index_[address] < 0) return nullptr;
  return &slaves_[static_cast<std::size_t>(index_[address])];
}

SlaveContext Master::context() {
  return SlaveContext{
      config_.address,      fcb_, events_, mode_ == OperatingMode::kClear, config_.auto_alarm_ack,
      config_.ready_timeout};
}

void Master::transmit(const fdl::Telegram& t) {
  ++counters_.telegrams_sent;
  queue_copy(t);
}

void Master::queue_copy(const fdl::Telegram& t) {
  keep_queued_request();  // stays ahead of `t`
  if (tx_head_ == tx_.size()) {  // all taken: the storage is reused
    tx_.clear();
    tx_head_ = 0;
  }
  tx_.push_back(t);
}

void Master::transmit_request() {
  ++counters_.telegrams_sent;
  keep_queued_request();  // (a link that did not drain since the last one)
  request_queued_ = true;
}

void Master::keep_queued_request() {
  if (!request_queued_) return;
  request_queued_ = false;
  queue_copy(outstanding_.request.telegram);
}

Request& Master::begin_outstanding() {
  outstanding_active_ = true;  // every field is set by next_request() and send_request()
  return outstanding_.request;
}

std::optional<fdl::Telegram> Master::take_transmit() {
  if (tx_head_ != tx_.size()) return std::move(tx_[tx_head_++]);
  if (!request_queued_) return std::nullopt;
  request_queued_ = false;
  return outstanding_.request.telegram;
}

const fdl::Telegram* Master::next_transmit(fdl::Telegram& /*scratch*/) {
  if (tx_head_ != tx_.size()) return &tx_[tx_head_++];
  if (!request_queued_) return nullptr;
  request_queued_ = false;
  return &outstanding_.request.telegram;  // kept there until its reply or expiry
}

std::optional<TimePoint> Master::send_time() const { return built_for_; }

void Master::on_malformed_frame(std::error_code why) {
  (void)why;
  ++counters_.malformed_frames;
}

std::optional<TimePoint> Master::next_deadline() const {
  if (!started_) return TimePoint{};  // run on_time() at once
  if (phase_ == MasterPhase::kListening) return listen_until_;
  if (outstanding_active_) return outstanding_.deadline;
  return next_send_;
}

void Master::on_time(TimePoint now) {
  built_for_.reset();  // what this call queues is due now
  if (!started_) {
    started_ = true;
    listen_until_ = now + config_.bus.token_lost_timeout(config_.address);
    next_send_ = now;
    next_gc_ = now;
  }
  if (phase_ == MasterPhase::kListening) {
    if (now < listen_until_) return;
    phase_ = MasterPhase::kClaimingToken;  // [IEC 61158-4-3 token]: TTO of silence
    next_send_ = now;
  }
  if (phase_ == MasterPhase::kClaimingToken) {
    if (now >= next_send_) claim_token_step(now);
    return;
  }
  run_bus(now);
}

void Master::claim_token_step(TimePoint now) {
  // [IEC 61158-4-3 token]: a lone master sends the token to itself twice, TSYN apart.
  const fdl::Telegram token = fdl::make_token(config_.address, config_.address);
  transmit(token);
  next_send_ = now + config_.bus.characters(fdl::encoded_size(token)) + config_.bus.bits(kTsynBits);
  if (++tokens_sent_ == 2) phase_ = MasterPhase::kRunning;
}

void Master::on_telegram(const fdl::Telegram& t, TimePoint now) {
  if (phase_ == MasterPhase::kListening) {
    if (started_) listen_until_ = now + config_.bus.token_lost_timeout(config_.address);
    return;  // another active station: keep listening ([IEC 61158-4-3 token, bus start])
  }
  if (!outstanding_active_ || t.type == fdl::FrameType::kToken) {
    ++counters_.ignored_telegrams;
    return;
  }
  SlaveHandler& slave = slaves_[outstanding_.slave];
  if (t.type != fdl::FrameType::kShortAck &&
      (t.fc.is_request() || t.da != config_.address || t.sa != slave.address())) {
    ++counters_.ignored_telegrams;
    return;
  }
  keep_queued_request();
  outstanding_active_ = false;
  ++counters_.replies;
  SlaveContext ctx = context();
  slave.on_reply(ctx, Reply::from(t), now);
  next_send_ = now + config_.bus.bits(config_.bus.tid1);
  if (send_time_honoured()) {
    // The link starts what this queues at next_send_: the turn goes on as of then.
    built_for_ = next_send_;
    run_bus(next_send_);
  }
}

void Master::send_request(std::size_t slave, TimePoint now) {
  cycle_sent_ = true;
  const BusParameters& b = config_.bus;
  Outstanding& o = outstanding_;
  o.slave = slave;
  o.deadline = now + b.characters(fdl::encoded_size(o.request.telegram)) + b.bits(b.tsl) +
               b.characters(o.request.max_reply_bytes);
  o.retries = 0;
  transmit_request();
}

void Master::on_slot_expired(TimePoint now) {
  ++counters_.slot_timeouts;
  Outstanding& o = outstanding_;
  SlaveHandler& slave = slaves_[o.slave];
  const fdl::FrameControl fc = o.request.telegram.fc;
  const bool first_frame = fc.fcb() && !fc.fcv();  // not retried ([IEC 61158-4-3 FCB/FCV])
  if (!first_frame && o.retries < config_.bus.max_retry_limit) {
    // [IEC 61158-4-3 FCB/FCV]: re-send with the same FCB.
    ++o.retries;
    slave.count_retry();
    const BusParameters& b = config_.bus;
    o.deadline = now + b.characters(fdl::encoded_size(o.request.telegram)) + b.bits(b.tsl) +
                 b.characters(o.request.max_reply_bytes);
    transmit_request();
    return;
  }
  keep_queued_request();
  outstanding_active_ = false;
  SlaveContext ctx = context();
  slave.on_no_answer(ctx);
  next_send_ = now;  // the line has been idle for TSL ≥ TSYN
}

void Master::run_bus(TimePoint now) {
  if (outstanding_active_) {
    if (now < outstanding_.deadline) return;
    on_slot_expired(now);
    if (outstanding_active_) return;
  }
  if (now < next_send_) return;
  for (;;) {
    if (!in_cycle_) {
      if (now < next_send_) return;
      start_cycle(now);
    }
    if (cursor_ == 0 && !turn_open_ && !gc_queue_.empty()) {
      const pdu::GlobalControl gc = gc_queue_.front();
      gc_queue_.pop_front();
      send_global_control(gc, now);
      return;
    }
    if (cursor_ >= slaves_.size()) {
      end_cycle(now);
      continue;
    }
    SlaveHandler& slave = slaves_[cursor_];
    if (!turn_open_) {
      slave.begin_turn();
      turn_open_ = true;
    }
    SlaveContext ctx = context();
    // The request is built in the slot it is kept in for a retry and sent from there.
    keep_queued_request();
    if (slave.next_request(ctx, now, begin_outstanding())) {
      send_request(cursor_, now);
      return;
    }
    outstanding_active_ = false;
    ++cursor_;
    turn_open_ = false;
  }
}

void Master::start_cycle(TimePoint now) {
  in_cycle_ = true;
  cycle_start_ = now;
  cursor_ = 0;
  turn_open_ = false;
  cycle_sent_ = false;
  SlaveContext ctx = context();
  for (SlaveHandler& s : slaves_) s.on_cycle_start(ctx, now);
  if (config_.global_control_interval > Duration::zero() && now >= next_gc_) {
    // [IEC 61158-6-3 class 1 master cycle]: the master repeats its operating state (Operate `00
    // 00`, Clear `02 00`).
    pdu::GlobalControl gc;
    gc.clear_data = mode_ == OperatingMode::kClear;
    if (gc_queue_.empty()) gc_queue_.push_back(gc);
    next_gc_ = now + config_.global_control_interval;
  }
}

void Master::end_cycle(TimePoint now) {
  in_cycle_ = false;
  ++counters_.cycles;
  counters_.last_cycle = now - cycle_start_;
  counters_.max_cycle = std::max(counters_.max_cycle, counters_.last_cycle);
  const auto in_dx = std::count_if(slaves_.begin(), slaves_.end(),
                                   [](const SlaveHandler& s) { return s.in_data_exchange(); });
  events_.push(CycleCompleted{counters_.cycles, static_cast<std::uint32_t>(in_dx)});
  TimePoint next = cycle_start_ + config_.cycle_target;
  if (!cycle_sent_) next = std::max(next, cycle_start_ + std::chrono::milliseconds(1));
  next_send_ = std::max(next, now);
  if (!cycle_sent_ && next_send_ <= now) next_send_ = now + std::chrono::milliseconds(1);
}

void Master::send_global_control(const pdu::GlobalControl& gc, TimePoint now) {
  // [IEC 61158-6-3 Global_Control]: SDN broadcast to DA 127, DSAP 58 from SSAP 62, e.g. `68 07 07
  // 68 FF 82 46 3A 3E
  // 02 00 41 16`; no reply, so the next request waits TID2.
  fdl::DataUnit du;
  (void)pdu::encode_global_control(gc, du);
  const fdl::Telegram t =
      fdl::make_data_telegram(fdl::kBroadcastAddress, config_.address,
                              fdl::FcbInitiator::unsequenced(fdl::RequestFunction::kSdnHigh),
                              pdu::sap::kGlobalControl, pdu::sap::kMasterMs0, bytes(du));
  cycle_sent_ = true;
  ++counters_.global_controls;
  next_send_ =
      now + config_.bus.characters(fdl::encoded_size(t)) + config_.bus.bits(config_.bus.tid2);
  transmit(t);
}

}  // namespace rs4sim::dp::master
