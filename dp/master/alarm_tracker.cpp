#include "dp/master/alarm_tracker.h"

#include "dp/master/master_error.h"
#include "dp/pdu/ext_diag.h"
#include "dp/pdu/sap.h"

#include <algorithm>
#include <array>

namespace rs4sim::dp::master {
namespace {

// Alarm_Mode 1..7 → outstanding alarms in total ([IEC 61158-6-3 DPV1_Status] DPV1_Status_3).
constexpr std::array<std::size_t, 8> kSequenceLimit{1, 2, 4, 8, 12, 16, 24, 32};

}  // namespace

bool AlarmTracker::known(const pdu::AlarmAck& k) const {
  const auto match = [&](const pdu::AlarmAck& o) { return same(o, k); };
  return std::any_of(outstanding_.begin(), outstanding_.end(),
                     [&](const Entry& e) { return match(e.key); }) ||
         std::any_of(acked_.begin(), acked_.end(), match);
}

bool AlarmTracker::exceeds_mode(const pdu::AlarmAck& k) const {
  if (alarm_mode_ == 0) {  // type mode: one outstanding alarm per type
    return std::any_of(outstanding_.begin(), outstanding_.end(),
                       [&](const Entry& e) { return e.key.alarm_type == k.alarm_type; });
  }
  return outstanding_.size() >= kSequenceLimit[alarm_mode_ & 0x07];
}

std::error_code AlarmTracker::on_diag(std::span<const std::uint8_t> ext_diag, bool auto_ack,
                                      EventQueue& events) {
  std::error_code result;
  Keys present;
  pdu::ExtDiagReader reader(ext_diag, true);
  for (;;) {
    auto block = reader.next();
    if (!block) {
      result = make_error_code(MasterError::kInvalidResponse);
      break;
    }
    if (!block.value()) break;
    const auto* alarm = std::get_if<pdu::AlarmPdu>(&*block.value());
    if (alarm == nullptr) continue;
    const pdu::AlarmAck key{alarm->slot, alarm->alarm_type, alarm->specifier_byte()};
    if (present.size() < present.capacity()) present.push_back(key);
    if (known(key)) continue;
    if (exceeds_mode(key)) result = make_error_code(MasterError::kAlarmLimitExceeded);
    if (outstanding_.size() == outstanding_.capacity()) continue;
    outstanding_.push_back(Entry{key, auto_ack, false});
    ++received_;
    events.push(AlarmReceived{address_, key.alarm_type, key.slot, key.specifier,
                              std::vector<std::uint8_t>(alarm->data.begin(), alarm->data.end())});
  }
  const auto gone = std::remove_if(acked_.begin(), acked_.end(), [&](const pdu::AlarmAck& k) {
    return std::none_of(present.begin(), present.end(),
                        [&](const pdu::AlarmAck& p) { return same(p, k); });
  });
  acked_.erase(gone, acked_.end());
  return result;
}

std::optional<pdu::AlarmAck> AlarmTracker::next_ack() {
  if (std::any_of(outstanding_.begin(), outstanding_.end(),
                  [](const Entry& e) { return e.ack_sent; })) {
    return std::nullopt;  // one Alarm_Ack in flight at a time
  }
  for (Entry& e : outstanding_) {
    if (e.ack_due) {
      e.ack_sent = true;
      return e.key;
    }
  }
  return std::nullopt;
}

void AlarmTracker::finish_in_flight(std::error_code result, std::optional<pdu::Dpv1Error> negative,
                                    EventQueue& events) {
  const auto it = std::find_if(outstanding_.begin(), outstanding_.end(),
                               [](const Entry& e) { return e.ack_sent; });
  if (it == outstanding_.end()) return;
  const pdu::AlarmAck key = it->key;
  outstanding_.erase(it);
  if (acked_.size() < acked_.capacity()) acked_.push_back(key);
  events.push(AlarmAcknowledged{address_, key, result, negative});
}

void AlarmTracker::on_ack_reply(const Reply& r, std::uint8_t reply_ssap, EventQueue& events) {
  if (r.empty_ack()) {  // accepted; the slave sent no echo
    finish_in_flight({}, std::nullopt, events);
    return;
  }
  if (!r.short_ack && r.status == fdl::ResponseStatus::kSapNotEnabled) {
    finish_in_flight(make_error_code(MasterError::kSapNotEnabled), std::nullopt, events);
    return;
  }
  const auto in_flight = std::find_if(outstanding_.begin(), outstanding_.end(),
                                      [](const Entry& e) { return e.ack_sent; });
  if (in_flight == outstanding_.end()) return;
  auto resp = r.carries_data() && r.from_saps(pdu::sap::kMasterMsac1, reply_ssap)
                  ? pdu::decode_c1_response(r.data)
                  : pdu::Result<pdu::C1Response>(make_error_code(pdu::PduError::kTooShort));
  if (resp) {
    if (const auto* echo = std::get_if<pdu::AlarmAck>(&resp.value());
        echo && *echo == in_flight->key) {
      finish_in_flight({}, std::nullopt, events);
      return;
    }
    if (const auto* neg = std::get_if<pdu::Dpv1Error>(&resp.value());
        neg && neg->function == pdu::Dpv1Function::kAlarmAck) {
      finish_in_flight(make_error_code(MasterError::kAlarmAckRejected), *neg, events);
      return;
    }
  }
  finish_in_flight(make_error_code(MasterError::kInvalidResponse), std::nullopt, events);
}

std::error_code AlarmTracker::acknowledge(std::uint8_t slot, std::uint8_t alarm_type,
                                          std::uint8_t seq_nr) {
  for (Entry& e : outstanding_) {
    if (e.key.slot == slot && e.key.alarm_type == alarm_type && e.key.seq_nr() == seq_nr &&
        !e.ack_due) {
      e.ack_due = true;
      return {};
    }
  }
  return make_error_code(MasterError::kAlarmNotOutstanding);
}

void AlarmTracker::reset() {
  outstanding_.clear();
  acked_.clear();
}

}  // namespace rs4sim::dp::master
