#pragma once
// The generic virtual slave: a dp::slave::SlaveApplication for any ident and configuration.
//
// * Set_Prm: every parameter set with the right ident is accepted (dp::slave::Slave already
//   refuses a wrong ident with Prm_Fault, [IEC 61158-6-3 Set_Prm]); User_Prm_Data are kept for
//   inspection.
// * Chk_Cfg: accepted only when the identifiers equal the real configuration byte for
//   byte ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]); anything else → Cfg_Fault. With DPV1 Check_Cfg_Mode
//   (user check) the device still requires the same I/O lengths (input and output bytes).
// * Data_Exchange: the outputs are looped back to the inputs. The image lengths come from
//   the identifiers; when input and output lengths differ, the first min(in, out) bytes
//   are copied and the rest of the inputs is 0.
// * DPV1 C1/C2 Read/Write: a small record store addressed by (slot, index), up to
//   kMaxRecords records of up to 240 bytes ([IEC 61158-6-3 MSAC_C1]). Read of an unknown record →
//   B0 invalid index; Write that would create a record beyond capacity → C3 resource unavailable.
//   Record (slot 0, index kAlarmTriggerIndex) is special: writing it raises a process alarm
//   (type 2) on slot 0 whose user data are the written bytes (≤ 59), so a remote master can provoke
//   an alarm round trip; its response is a normal Write.res.
// * raise_alarm(): the application side of the same, for tests, the demo and the CLI.

#include "dp/pdu/cfg.h"
#include "dp/slave/slave_application.h"

#include <boost/container/static_vector.hpp>

#include <cstdint>
#include <map>
#include <system_error>
#include <vector>

namespace rs4sim::dp::devices {

struct GenericDeviceConfig {
  std::vector<std::uint8_t> cfg;  // real configuration identifiers (Get_Cfg reply,
                                  // [IEC 61158-6-3 Chk_Cfg/Get_Cfg])
};

class GenericDevice final : public dp::slave::SlaveApplication {
 public:
  static constexpr std::size_t kMaxRecords = 32;
  static constexpr std::uint8_t kAlarmTriggerIndex = 200;

  // Throws std::system_error (dp.pdu category) if the identifiers do not parse
  // ([IEC 61158-6-3 Chk_Cfg/Get_Cfg]) or the images exceed 244 bytes.
  explicit GenericDevice(GenericDeviceConfig config);

  // ---- SlaveApplication ----
  void on_attach(dp::slave::SlaveControl& control) override { control_ = &control; }
  dp::slave::PrmVerdict check_parameters(const pdu::SetPrm& prm, TimePoint now) override;
  dp::slave::CfgVerdict check_config(std::span<const std::uint8_t> cfg, bool user_check,
                                     TimePoint now) override;
  [[nodiscard]] std::span<const std::uint8_t> real_config() const override { return cfg_; }
  void on_outputs(std::span<const std::uint8_t> outputs, TimePoint now) override;
  void on_outputs_cleared(dp::slave::OutputClear why, TimePoint now) override;
  void read_inputs(std::span<std::uint8_t> inputs, TimePoint now) override;
  void on_state_change(dp::slave::State from, dp::slave::State to, dp::slave::TransitionReason why,
                       TimePoint now) override;
  dp::slave::AcyclicResult on_acyclic(const dp::slave::AcyclicRequest& req, TimePoint now) override;
  void on_alarm_acknowledged(const dp::slave::AlarmAck& ack, TimePoint now) override;

  // ---- control and observation ----
  // Submits a process alarm; errors as SlaveControl::submit_alarm (alarms closed, type
  // not enabled by the master, queue full) or kNotAttached-like std::errc::not_connected.
  std::error_code raise_alarm(std::uint8_t type, std::uint8_t slot,
                              std::span<const std::uint8_t> user_data);
  [[nodiscard]] std::size_t input_length() const { return input_length_; }
  [[nodiscard]] std::size_t output_length() const { return output_length_; }
  [[nodiscard]] std::span<const std::uint8_t> outputs() const {
    return {outputs_.data(), outputs_.size()};
  }
  [[nodiscard]] std::uint64_t exchanges() const { return exchanges_; }
  [[nodiscard]] dp::slave::State state() const { return state_; }
  [[nodiscard]] const std::vector<dp::slave::AlarmAck>& acknowledged_alarms() const {
    return acked_;
  }
  [[nodiscard]] std::span<const std::uint8_t> user_prm_data() const {
    return {user_prm_.data(), user_prm_.size()};
  }
  [[nodiscard]] const std::vector<std::uint8_t>* record(std::uint8_t slot,
                                                        std::uint8_t index) const;

 private:
  dp::slave::AcyclicResult read_record(const dp::slave::AcyclicRequest& req) const;
  dp::slave::AcyclicResult write_record(const dp::slave::AcyclicRequest& req);

  dp::slave::SlaveControl* control_ = nullptr;
  std::vector<std::uint8_t> cfg_;
  std::size_t input_length_ = 0;
  std::size_t output_length_ = 0;
  boost::container::static_vector<std::uint8_t, 244> outputs_;
  boost::container::static_vector<std::uint8_t, 244> user_prm_;
  std::map<std::uint16_t, std::vector<std::uint8_t>> records_;  // key = slot << 8 | index
  std::vector<dp::slave::AlarmAck> acked_;
  std::uint64_t exchanges_ = 0;
  dp::slave::State state_ = dp::slave::State::kWaitPrm;
};

}  // namespace rs4sim::dp::devices
