#pragma once
// DPV1 alarm state machine of the slave, [IEC 61158-6-3 DPV1 alarms] (model: the profichip
// DPV1 driver [VPC3+ dp_msac1.c AL_*]).
//
//   submit() → pending queue → take_next() (when the previous diagnosis was fetched and
//   the Alarm_Mode limit allows) → outstanding, written once into a diagnosis → the
//   master's Alarm_Ack (slot, type, Seq_Nr) → acknowledge() frees it.
// An alarm is never sent twice; a new one waits until an outstanding one is acknowledged.

#include "dp/pdu/set_prm.h"
#include "dp/slave/slave_application.h"

#include <boost/container/static_vector.hpp>

#include <cstdint>
#include <deque>
#include <optional>
#include <system_error>

namespace rs4sim::dp::slave {

struct Alarm {
  std::uint8_t type = 0;
  std::uint8_t slot = 0;
  std::uint8_t specifier = 0;  // bits 1..0
  bool add_ack = false;
  std::uint8_t seq_nr = 0;  // assigned by take_next()
  boost::container::static_vector<std::uint8_t, kMaxAlarmUserData> user_data;

  // Alarm block: [00LLLLLL][type][slot][Seq_Nr<<3 | Add_Ack<<2 | specifier][data…]
  // ([IEC 61158-6-3 DPV1 alarms]).
  [[nodiscard]] std::size_t block_size() const { return 4 + user_data.size(); }
  template <class Out>
  void append_block(Out& out) const {
    out.push_back(static_cast<std::uint8_t>(block_size()));
    out.push_back(type);
    out.push_back(slot);
    out.push_back(static_cast<std::uint8_t>((seq_nr << 3) | (add_ack ? 0x04 : 0) | specifier));
    out.insert(out.end(), user_data.begin(), user_data.end());
  }
};

class AlarmQueue {
 public:
  AlarmQueue(std::uint8_t capacity, std::uint8_t sequence_numbers, std::uint8_t queue_limit);

  // Opens on entering Data_Exch with the master's DPV1 settings ([IEC 61158-6-3 MSAC_C1]): the
  // enabled types (DPV1_Status_2) and the limit from Alarm_Mode (0 = one per type), bounded by
  // capacity.
  void open(const pdu::Dpv1Status& dpv1);
  // Closes: clears both queues ([IEC 61158-6-3 MSAC_C1] "closing clears … the alarm queues").
  void close();
  [[nodiscard]] bool is_open() const { return open_; }

  std::error_code submit(const AlarmRequest& a);
  // The next alarm that may go into a diagnosis now, moved to the outstanding set.
  std::optional<Alarm> take_next();
  // Matches an Alarm_Ack; returns false if no outstanding alarm has (slot, type, seq).
  bool acknowledge(std::uint8_t slot, std::uint8_t type, std::uint8_t seq_nr);

  [[nodiscard]] std::size_t pending() const { return pending_.size(); }
  [[nodiscard]] std::size_t outstanding() const { return outstanding_.size(); }
  [[nodiscard]] unsigned limit() const { return limit_; }
  [[nodiscard]] bool type_mode() const { return type_mode_; }

 private:
  struct Outstanding {
    std::uint8_t type, slot, seq_nr;
  };
  [[nodiscard]] bool type_enabled(std::uint8_t type) const;
  [[nodiscard]] bool may_send(const Alarm& a) const;
  [[nodiscard]] std::uint8_t next_free_seq();

  std::uint8_t capacity_;
  std::uint8_t sequence_numbers_;
  std::uint8_t queue_limit_;
  bool open_ = false;
  bool type_mode_ = false;
  unsigned limit_ = 0;
  pdu::Dpv1Status dpv1_{};
  std::uint8_t next_seq_ = 0;
  std::deque<Alarm> pending_;
  boost::container::static_vector<Outstanding, 32> outstanding_;
};

}  // namespace rs4sim::dp::slave
