#pragma once
// What the class 1 master reports upward ([docs/design.md#sans-io-cores],
// [docs/design.md#upward-events]).
//
// The core never calls user code: it appends events to a queue that the owner drains
// with Master::take_events() after each on_time()/on_telegram(). `dispatch` hands one
// event to a MasterObserver for owners that prefer callbacks.

#include "dp/fdl/telegram.h"
#include "dp/pdu/dpv1.h"

#include <cstdint>
#include <optional>
#include <system_error>
#include <variant>
#include <vector>

namespace rs4sim::dp::master {

// Identifies one DPV1 Read/Write request; unique per master, never 0.
using Dpv1RequestId = std::uint32_t;

// [IEC 61158-6-3 master start-up of a slave] [pyprofibus dp_master.py] step 5 reached: the slave is
// in cyclic Data_Exchange.
struct SlaveEnteredDataExchange {
  std::uint8_t address = 0;
};

// The slave left cyclic Data_Exchange ([IEC 61158-6-3 slave supervision]); `reason` says why
// (kNoAnswer, kSapNotEnabled, kLeftDataExchange, kInvalidResponse, …). Its start-up restarts.
struct SlaveLeftDataExchange {
  std::uint8_t address = 0;
  std::error_code reason;
};

// Start-up or supervision of a slave failed with a new reason (reported once per change,
// not once per retry).
struct SlaveFault {
  std::uint8_t address = 0;
  std::error_code reason;
};

// A Slave_Diag reply with new content, or one fetched because of a DH reply
// ([IEC 61158-6-3 Data_Exchange]).
struct DiagReceived {
  std::uint8_t address = 0;
  fdl::DataUnit diag;  // the complete Slave_Diag DU ([IEC 61158-6-3 Slave_Diag])
};

// A DPV1 alarm found in the extended diagnosis ([IEC 61158-6-3 DPV1 alarms]).
struct AlarmReceived {
  std::uint8_t address = 0;
  std::uint8_t alarm_type = 0;
  std::uint8_t slot = 0;
  std::uint8_t specifier = 0;      // Alarm_Specifier byte: Seq_Nr<<3 | Add_Ack<<2 | bits 1..0
  std::vector<std::uint8_t> data;  // Diagnostic_User_Data
  [[nodiscard]] std::uint8_t seq_nr() const { return static_cast<std::uint8_t>(specifier >> 3); }
  [[nodiscard]] bool add_ack() const { return (specifier & 0x04) != 0; }
};

// Alarm_Ack answered: `result` empty = positive echo; kAlarmAckRejected with `negative`.
struct AlarmAcknowledged {
  std::uint8_t address = 0;
  pdu::AlarmAck ack;
  std::error_code result;
  std::optional<pdu::Dpv1Error> negative;
};

enum class Dpv1Operation : std::uint8_t { kRead, kWrite };

// Completion of a DPV1 Read/Write ([IEC 61158-6-3 MSAC_C1 polling]). `error` empty = success; a
// negative response carries its bytes in `negative` and error = to_error_code(*negative);
// kDpv1Timeout, kNoAnswer, kAborted, kSapNotEnabled, kInvalidResponse are the other outcomes.
struct Dpv1Result {
  Dpv1RequestId id = 0;
  std::uint8_t address = 0;
  Dpv1Operation operation = Dpv1Operation::kRead;
  std::uint8_t slot = 0;
  std::uint8_t index = 0;
  std::error_code error;
  std::optional<pdu::Dpv1Error> negative;
  pdu::Dpv1Data data;       // Read: the bytes returned
  std::uint8_t length = 0;  // Write: the Length echoed by the slave
};

// One poll cycle over all slaves ended.
struct CycleCompleted {
  std::uint64_t cycle = 0;
  std::uint32_t slaves_in_data_exchange = 0;
};

using MasterEvent =
    std::variant<SlaveEnteredDataExchange, SlaveLeftDataExchange, SlaveFault, DiagReceived,
                 AlarmReceived, AlarmAcknowledged, Dpv1Result, CycleCompleted>;

class MasterObserver {
 public:
  virtual ~MasterObserver() = default;
  virtual void on_entered_data_exchange(const SlaveEnteredDataExchange&) {}
  virtual void on_left_data_exchange(const SlaveLeftDataExchange&) {}
  virtual void on_slave_fault(const SlaveFault&) {}
  virtual void on_diag(const DiagReceived&) {}
  virtual void on_alarm(const AlarmReceived&) {}
  virtual void on_alarm_acknowledged(const AlarmAcknowledged&) {}
  virtual void on_dpv1_result(const Dpv1Result&) {}
  virtual void on_cycle(const CycleCompleted&) {}
};

void dispatch(const MasterEvent& e, MasterObserver& observer);

}  // namespace rs4sim::dp::master
