#include "dp/slave/alarm_queue.h"

#include "dp/slave/slave_error.h"

#include <algorithm>

namespace rs4sim::dp::slave {

AlarmQueue::AlarmQueue(std::uint8_t capacity, std::uint8_t sequence_numbers,
                       std::uint8_t queue_limit)
    : capacity_(capacity), sequence_numbers_(sequence_numbers), queue_limit_(queue_limit) {}

void AlarmQueue::open(const pdu::Dpv1Status& dpv1) {
  close();
  dpv1_ = dpv1;
  open_ = true;
  type_mode_ = dpv1.alarm_mode == 0;
  // Alarm_Mode 0 = type mode: one outstanding per type, in total at most `capacity_`.
  limit_ = type_mode_ ? capacity_ : std::min<unsigned>(dpv1.max_outstanding_alarms(), capacity_);
}

void AlarmQueue::close() {
  open_ = false;
  pending_.clear();
  outstanding_.clear();
  next_seq_ = 0;
}

bool AlarmQueue::type_enabled(std::uint8_t type) const {
  switch (type) {
    case 1: return dpv1_.enable_diagnostic_alarm;
    case 2: return dpv1_.enable_process_alarm;
    case 3:
    case 4: return dpv1_.enable_pull_plug_alarm;
    case 5: return dpv1_.enable_status_alarm;
    case 6: return dpv1_.enable_update_alarm;
    default: return type >= 32 && type <= 126 && dpv1_.enable_manufacturer_specific_alarm;
  }
}

std::error_code AlarmQueue::submit(const AlarmRequest& a) {
  const bool type_valid = (a.type >= 1 && a.type <= 6) || (a.type >= 32 && a.type <= 126);
  if (!type_valid || a.slot == 255 || a.specifier > 3 || a.user_data.size() > kMaxAlarmUserData) {
    return SlaveError::kInvalidAlarm;
  }
  if (!open_) return SlaveError::kAlarmsClosed;
  if (!type_enabled(a.type)) return SlaveError::kAlarmTypeNotEnabled;
  if (pending_.size() >= queue_limit_) return SlaveError::kAlarmQueueFull;
  Alarm alarm;
  alarm.type = a.type;
  alarm.slot = a.slot;
  alarm.specifier = a.specifier;
  alarm.add_ack = a.add_ack;
  alarm.user_data.assign(a.user_data.begin(), a.user_data.end());
  pending_.push_back(std::move(alarm));
  return {};
}

bool AlarmQueue::may_send(const Alarm& a) const {
  if (outstanding_.size() >= limit_) return false;
  if (!type_mode_) return true;
  return std::none_of(outstanding_.begin(), outstanding_.end(),
                      [&](const Outstanding& o) { return o.type == a.type; });
}

std::uint8_t AlarmQueue::next_free_seq() {
  // Seq_Nr unique among outstanding alarms ([IEC 61158-6-3 DPV1 alarms]); capacity ≤ sequence
  // numbers, so a free one always exists when may_send() said yes.
  for (unsigned tries = 0; tries < sequence_numbers_; ++tries) {
    const std::uint8_t seq = next_seq_;
    next_seq_ = static_cast<std::uint8_t>((next_seq_ + 1) % sequence_numbers_);
    const bool used = std::any_of(outstanding_.begin(), outstanding_.end(),
                                  [&](const Outstanding& o) { return o.seq_nr == seq; });
    if (!used) return seq;
  }
  return next_seq_;  // unreachable with a validated config
}

std::optional<Alarm> AlarmQueue::take_next() {
  if (!open_) return std::nullopt;
  // In type mode an alarm of a type that is still outstanding must not block the others.
  for (auto it = pending_.begin(); it != pending_.end(); ++it) {
    if (!may_send(*it)) continue;
    Alarm a = std::move(*it);
    pending_.erase(it);
    a.seq_nr = next_free_seq();
    outstanding_.push_back({a.type, a.slot, a.seq_nr});
    return a;
  }
  return std::nullopt;
}

bool AlarmQueue::acknowledge(std::uint8_t slot, std::uint8_t type, std::uint8_t seq_nr) {
  const auto it = std::find_if(outstanding_.begin(), outstanding_.end(), [&](const Outstanding& o) {
    return o.slot == slot && o.type == type && o.seq_nr == seq_nr;
  });
  if (it == outstanding_.end()) return false;
  outstanding_.erase(it);
  return true;
}

}  // namespace rs4sim::dp::slave
