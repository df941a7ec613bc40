#pragma once
// How a device plugs into dp::Slave ([docs/design.md#layers]: the RS4 adapter, the loopback
// device).
//
// The slave owns the protocol (FDL, FCB, states, watchdog, diagnosis, alarm queue, the
// DPV1 polling pattern); the application owns the meaning of parameters, configuration,
// I/O data and records. It never sees telegrams, SAPs or FCBs.
//
//   slave → application: SlaveApplication (virtual on_*/check_* calls, always from the
//                        slave's own on_telegram()/on_time(), one thread, no re-entry
//                        needed: the application may call SlaveControl from inside them).
//                        Every call carries the link's `now`: no application keeps its
//                        own copy of the time.
//   application → slave: SlaveControl (complete an acyclic request later, submit an
//                        alarm, set the device-related diagnosis blocks)

#include "dp/pdu/error_code_1.h"
#include "dp/pdu/set_prm.h"
#include "dp/time/clock.h"

#include <boost/container/static_vector.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <system_error>

namespace rs4sim::dp::slave {

// Slave states, [IEC 61158-6-3 slave state machine] (VPC3 names: WAIT_PRM, WAIT_CFG, DATA_EX).
enum class State : std::uint8_t { kWaitPrm, kWaitCfg, kDataExch };
[[nodiscard]] const char* to_string(State s);  // "Wait_Prm", "Wait_Cfg", "Data_Exch"

// Why the state changed (trace and application notification).
enum class TransitionReason : std::uint8_t {
  kPrmAccepted,        // Set_Prm taken over (→ Wait_Cfg)
  kPrmFault,           // Set_Prm refused: ident, factors, user prm … (→ Wait_Prm)
  kNotSupported,       // Set_Prm asked for a feature the slave lacks (→ Wait_Prm)
  kCfgAccepted,        // Chk_Cfg accepted (→ Data_Exch)
  kCfgFault,           // Chk_Cfg refused (→ Wait_Prm)
  kUnlock,             // Set_Prm with Unlock_Req released the slave (→ Wait_Prm)
  kWatchdog,           // no telegram from the master within T_WD ([IEC 61158-6-3 watchdog]) (→
                       // Wait_Prm)
  kProtocolViolation,  // unmatched Alarm_Ack / unknown C1 function
                       // ([IEC 61158-6-3 MSAC_C1, DPV1 alarms])
  kAddressChanged,     // Set_Slave_Add took effect (stays Wait_Prm)
};
[[nodiscard]] const char* to_string(TransitionReason r);

// Why the application must put its outputs into the safe state.
enum class OutputClear : std::uint8_t {
  kGlobalControlClear,  // Global_Control Clear_Data ([IEC 61158-6-3 Global_Control])
  kFailSafe,            // empty Data_Exchange from a Fail_Safe master in CLEAR
                        // ([IEC 61158-6-3 Data_Exchange])
  kLeftDataExchange,  // watchdog, new Set_Prm, Cfg_Fault … ([IEC 61158-6-3 slave state machine])
};

// Verdicts on the master's parameters and configuration ([IEC 61158-6-3 Set_Prm, Chk_Cfg/Get_Cfg]).
enum class PrmVerdict : std::uint8_t { kAccept, kPrmFault, kNotSupported };
enum class CfgVerdict : std::uint8_t { kAccept, kCfgFault };

// ---- DPV1 acyclic services ([IEC 61158-6-3 MSAC_C1, MSAC_C2]) -----------------------------------
enum class AcyclicChannel : std::uint8_t { kC1, kC2 };
enum class AcyclicService : std::uint8_t { kRead = 0x5E, kWrite = 0x5F, kDataTransport = 0x51 };

inline constexpr std::size_t kMaxAcyclicData = 240;  // 4-byte header + 240 = 244
                                                     // ([IEC 61158-6-3 MSAC_C1])
using AcyclicData = boost::container::static_vector<std::uint8_t, kMaxAcyclicData>;

struct AcyclicRequest {
  AcyclicChannel channel = AcyclicChannel::kC1;  // the RS4 forbids adapter commands on C2
  AcyclicService service = AcyclicService::kRead;
  std::uint8_t master_address = 0;
  std::uint8_t slot = 0;
  std::uint8_t index = 0;
  std::uint8_t length = 0;                  // Read: max bytes wanted; Write/Transport: data size
  std::span<const std::uint8_t> data;       // Write/Data_Transport payload (valid during the call)
  bool first_write_after_initiate = false;  // C2 only: RS4 raises an update alarm
                                            // ([RS4 manual §5.3.1])
};

// Negative response `(Fn|0x80) Error_Decode Error_Code_1 Error_Code_2` ([IEC 61158-6-3 MSAC_C1]).
struct AcyclicError {
  std::uint8_t error_decode = 0x80;                       // 0x80 = DPV1
  pdu::ErrorCode1 error_code_1 = pdu::ErrorCode1::kNone;  // class|code, e.g. 0xB0
  std::uint8_t error_code_2 = 0;
  friend bool operator==(const AcyclicError&, const AcyclicError&) = default;
};

// The application's answer: data (Read / Data_Transport; empty for a Write), an error,
// or "pending" (the answer comes later through SlaveControl::complete_acyclic()).
struct AcyclicResult {
  enum class Kind : std::uint8_t { kData, kError, kPending };
  Kind kind = Kind::kPending;
  AcyclicData data;
  AcyclicError error;

  static AcyclicResult ok(std::span<const std::uint8_t> bytes = {});  // throws if > 240 B
  static AcyclicResult fail(AcyclicError e) { return {Kind::kError, {}, e}; }
  static AcyclicResult pending() { return {}; }
};

// ---- Alarms ([IEC 61158-6-3 DPV1 alarms]) -------------------------------------------------------
inline constexpr std::size_t kMaxAlarmUserData = 59;  // block ≤ 63 incl. 4-byte head

struct AlarmRequest {
  std::uint8_t type = 1;       // 1 diagnostic, 2 process, 3 pull, 4 plug, 5 status,
                               // 6 update, 32…126 manufacturer specific
  std::uint8_t slot = 0;       // 0…254
  std::uint8_t specifier = 0;  // bits 1..0: 0 none, 1 appears, 2 disappears, 3 disappears/faulty
  bool add_ack = false;        // Add_Ack: the master application must confirm as well
  std::span<const std::uint8_t> user_data;  // ≤ 59 bytes
};

// What the master acknowledged (Alarm_Ack matched on slot, type and Seq_Nr).
struct AlarmAck {
  std::uint8_t type = 0;
  std::uint8_t slot = 0;
  std::uint8_t seq_nr = 0;
};

enum class C2Event : std::uint8_t {
  kConnected,        // Initiate accepted
  kAbortedByMaster,  // Abort.req from the master
  kTimedOut,         // no request within Send_Timeout ([IEC 61158-6-3 MSAC_C2])
  kRefused,          // Initiate.req invalid: Abort sent instead of Initiate.res
  kAbortedBySlave,   // invalid request PDU on the connection: Abort sent, SAP freed
};

// ---- application → slave ---------------------------------------------------------------
class SlaveControl {
 public:
  // Answers the acyclic request the application left pending on `channel`; the slave
  // sends it on the master's next poll ([IEC 61158-6-3 MSAC_C1 polling]). kNoPendingRequest if
  // there is none.
  virtual std::error_code complete_acyclic(AcyclicChannel channel, const AcyclicResult& r) = 0;
  // Queues an alarm; the slave assigns the Seq_Nr and puts it into a diagnosis when the
  // previous diagnosis was fetched. Errors: kAlarmsClosed, kAlarmTypeNotEnabled,
  // kAlarmQueueFull, kInvalidAlarm.
  virtual std::error_code submit_alarm(const AlarmRequest& a) = 0;
  // Replaces the device's extended diagnosis blocks ([IEC 61158-6-3 Slave_Diag] blocks, e.g. the
  // PROFIsafe status PDU 05 81 00 00 nn) and its Ext_Diag / Stat_Diag bits; a change raises the
  // diagnosis flag (DH on Data_Exchange). Errors: kDiagnosisTooLong, kInvalidDiagnosisBlock.
  virtual std::error_code set_device_diagnosis(std::span<const std::uint8_t> blocks, bool ext_diag,
                                               bool stat_diag) = 0;

 protected:
  ~SlaveControl() = default;
};

// ---- slave → application ---------------------------------------------------------------
class SlaveApplication {
 public:
  virtual ~SlaveApplication() = default;

  // Called once by the Slave constructor.
  virtual void on_attach(SlaveControl& control) { (void)control; }

  // Set_Prm with a matching ident: check the User_Prm_Data (after the DPV1 bytes).
  virtual PrmVerdict check_parameters(const pdu::SetPrm& prm, TimePoint now) = 0;
  // Chk_Cfg: compare with the real configuration; `user_check` = DPV1 Check_Cfg_Mode.
  virtual CfgVerdict check_config(std::span<const std::uint8_t> cfg, bool user_check,
                                  TimePoint now) = 0;
  // Get_Cfg reply: the real configuration identifiers ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]).
  [[nodiscard]] virtual std::span<const std::uint8_t> real_config() const = 0;

  // Data_Exchange outputs (length as configured by the accepted Chk_Cfg).
  virtual void on_outputs(std::span<const std::uint8_t> outputs, TimePoint now) = 0;
  virtual void on_outputs_cleared(OutputClear why, TimePoint now) = 0;
  // Fills the input image (length as configured) for the Data_Exchange reply.
  virtual void read_inputs(std::span<std::uint8_t> inputs, TimePoint now) = 0;

  virtual void on_state_change(State from, State to, TransitionReason why, TimePoint now) {
    (void)from, (void)to, (void)why, (void)now;
  }

  // DPV1 Read/Write/Data_Transport. Default: "feature not supported" (A9).
  virtual AcyclicResult on_acyclic(const AcyclicRequest& req, TimePoint now) {
    (void)req, (void)now;
    return AcyclicResult::fail({0x80, pdu::ErrorCode1::kFeatureNotSupported, 0x00});
  }
  virtual void on_alarm_acknowledged(const AlarmAck& ack, TimePoint now) { (void)ack, (void)now; }
  virtual void on_c2_event(C2Event ev, std::uint8_t master, TimePoint now) {
    (void)ev, (void)master, (void)now;
  }
  // Set_Slave_Add took effect: persist the new address (and the No_Add_Chg lock).
  virtual void on_address_changed(std::uint8_t new_address, bool no_add_chg,
                                  std::span<const std::uint8_t> rem_slave_data, TimePoint now) {
    (void)new_address, (void)no_add_chg, (void)rem_slave_data, (void)now;
  }

  // The application's own timer, folded into the slave's next_deadline().
  [[nodiscard]] virtual std::optional<TimePoint> next_deadline() const { return std::nullopt; }
  virtual void on_time(TimePoint now) { (void)now; }
};

}  // namespace rs4sim::dp::slave
