#pragma once
// DPV1 alarms of one slave as seen by the master ([IEC 61158-6-3 DPV1 alarms]).
//
// Alarms arrive in the device-related blocks of the extended diagnosis. Each new alarm
// (slot, type, Seq_Nr) is delivered once as AlarmReceived and waits for its Alarm_Ack
// (`5C Slot Alarm_Type Alarm_Specifier`, the full specifier byte echoed), sent
// automatically or when the user acknowledges it. Acks go out in arrival order. An alarm
// that was acknowledged but still appears in later diagnoses (the slave need not remove
// it, [IEC 61158-6-3 DPV1 alarms] [VPC3+ dp_msac1.c]) is not delivered again; once a diagnosis no
// longer contains it, the same key counts as new again. Alarm_Mode is honoured by checking the
// slave: more outstanding alarms than the mode allows (type mode: one per type; sequence
// mode: 2..32 in total) is reported as kAlarmLimitExceeded.

#include "dp/master/event_queue.h"
#include "dp/master/reply.h"
#include "dp/pdu/dpv1.h"

#include <boost/container/static_vector.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <system_error>

namespace rs4sim::dp::master {

class AlarmTracker {
 public:
  static constexpr std::size_t kMaxOutstanding = 32;

  // `alarm_mode` = DPV1_Status_3 bits 2..0 from the slave's Set_Prm ([IEC 61158-6-3 DPV1_Status]).
  AlarmTracker(std::uint8_t slave_address, std::uint8_t alarm_mode)
      : address_(slave_address), alarm_mode_(alarm_mode) {}

  // Scans the extended diagnosis; delivers new alarms. Returns kAlarmLimitExceeded when
  // the slave exceeds its Alarm_Mode, kInvalidResponse for malformed blocks, else {}.
  std::error_code on_diag(std::span<const std::uint8_t> ext_diag, bool auto_ack,
                          EventQueue& events);

  // The next Alarm_Ack to send (marks it as sent), nullopt if none is due.
  std::optional<pdu::AlarmAck> next_ack();
  // Evaluates the reply to the Alarm_Ack from next_ack().
  void on_ack_reply(const Reply& r, std::uint8_t reply_ssap, EventQueue& events);
  // The user acknowledges an outstanding alarm (manual mode). kAlarmNotOutstanding if
  // no such alarm waits.
  std::error_code acknowledge(std::uint8_t slot, std::uint8_t alarm_type, std::uint8_t seq_nr);

  // The slave left data exchange: its alarm machine is closed ([IEC 61158-6-3 MSAC_C1]), forget
  // everything.
  void reset();

  [[nodiscard]] std::size_t outstanding() const { return outstanding_.size(); }
  [[nodiscard]] std::uint64_t received() const { return received_; }

 private:
  struct Entry {
    pdu::AlarmAck key;
    bool ack_due = false;   // auto or user requested
    bool ack_sent = false;  // in flight
  };
  using Keys = boost::container::static_vector<pdu::AlarmAck, kMaxOutstanding>;
  static bool same(const pdu::AlarmAck& a, const pdu::AlarmAck& b) {
    return a.slot == b.slot && a.alarm_type == b.alarm_type && a.seq_nr() == b.seq_nr();
  }
  [[nodiscard]] bool known(const pdu::AlarmAck& k) const;
  [[nodiscard]] bool exceeds_mode(const pdu::AlarmAck& k) const;
  void finish_in_flight(std::error_code result, std::optional<pdu::Dpv1Error> negative,
                        EventQueue& events);

  std::uint8_t address_;
  std::uint8_t alarm_mode_;
  boost::container::static_vector<Entry, kMaxOutstanding> outstanding_;
  Keys acked_;  // acknowledged, still present in the last diagnosis
  std::uint64_t received_ = 0;
};

}  // namespace rs4sim::dp::master
