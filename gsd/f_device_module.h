#pragma once
// A GSD station's F-module as a PROFIsafe F-device ([IEC 61784-3-3 F-Parameters, safety PDU];
// docs/gsd.md "PROFIsafe F-modules"): sans-I/O, between the DP slave's bytes and
// profisafe::FDevice.
//
//   * Set_Prm: the module's 10-byte F-parameter block at its place in User_Prm_Data is checked
//     as the device checks it: F_Dest_Add against the device's own (its address switch),
//     F_Source_Add and F_WD_Time against the GSD's ranges, SIL, CRC length, F_Par_Version and
//     F_Block_ID against the GSD's defaults, F_Par_CRC = CRC1. A refused block gives the
//     standard diagnosis 64..71 as a DP-V1 status block `05 81 slot 00 nn`
//     ([IEC 61158-6-3 DPV1 status]).
//   * Data_Exchange: the module's output bytes are the host's safety PDU, its input bytes the
//     device's answer (V1 or V2 as the F-parameters select); the F-input data are the
//     harness's, the F-output data reach it only while the device sends process values.
//   * Faults a PLC test provokes (docs/profisafe.md "GSD F-devices"): those of the PDUs it
//     sends (device().faults(): corrupt CRC2, skipped or repeated consecutive number), answers
//     held back (hold_answers: the last PDU stays on the wire, as from a device that answers
//     late) and another address switch (restart: a device powered up with another F_Dest_Add).

#include "gsd/config.h"
#include "gsd/f_module.h"
#include "profisafe/f_device.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace rs4sim::gsd {

class FModuleDevice {
 public:
  // The F-device of the placed module `block.module` of `setup`, whose bytes start at
  // input_offset / output_offset of the station's images; its own F_Dest_Add is `dest_add`.
  // Errors: kFParameterLayout (F-data not the same size both ways or 0 or beyond 12 bytes: the
  // drivers serve 1..12 bytes each way, equal).
  static Result<FModuleDevice> make(const Device& device, const SlaveSetup& setup,
                                    const FParameterBlock& block, std::size_t input_offset,
                                    std::size_t output_offset, std::uint16_t dest_add);

  // The F-parameters out of the Set_Prm user data (the same length as the configuration's).
  profisafe::Validation set_parameters(std::span<const std::uint8_t> user_prm_data);
  [[nodiscard]] std::uint8_t diagnosis() const noexcept { return device_.diagnosis(); }
  // `05 81 slot 00 nn`: the status block of the last refused F-parameters.
  [[nodiscard]] std::array<std::uint8_t, 5> status_block() const noexcept;

  // The station's output image (the master's bytes): the module's part is the host's PDU.
  void on_outputs(std::span<const std::uint8_t> outputs, profisafe::TimePoint now);
  // The module's part of the station's input image: the device's PDU; while muted or held
  // (hold_answers) the PDU sent last, so the host sees no new one.
  void write_inputs(std::span<std::uint8_t> inputs, profisafe::TimePoint now);
  // The device's F-input data (what a real device's sensors read); size = f_data_size().
  void set_f_inputs(std::span<const std::uint8_t> data);
  [[nodiscard]] std::span<const std::uint8_t> f_inputs() const noexcept {
    return std::span<const std::uint8_t>(f_inputs_).first(data_size_);
  }
  // The host's F-output data as the device delivers them (0 while fail-safe).
  [[nodiscard]] std::span<const std::uint8_t> f_outputs() const noexcept {
    return device_.output();
  }
  [[nodiscard]] std::size_t f_data_size() const noexcept { return data_size_; }
  [[nodiscard]] std::size_t module() const noexcept { return module_; }
  [[nodiscard]] int slot() const noexcept { return slot_; }
  // The device's own F_Dest_Add (its address switch).
  [[nodiscard]] std::uint16_t dest_add() const noexcept { return config_.profile.dest_add; }
  // Power-up with the address switch at `dest_add`: no F-parameters, no faults pending, the
  // F-input data kept.
  void restart(std::uint16_t dest_add);
  // The answers held back for `d` from the next poll on (the PDU sent last stays on the wire):
  // a device that answers late; a hold longer than F_WD_Time is a timeout at the host.
  void hold_answers(std::chrono::milliseconds d) noexcept {
    hold_ = d;
    held_until_.reset();
  }
  // The hold asked for while it lasts (pending or running), else 0.
  [[nodiscard]] std::chrono::milliseconds hold() const noexcept { return hold_; }
  // F_WD_Time of the F-parameters taken (0 before).
  [[nodiscard]] std::uint16_t wd_time_ms() const noexcept { return wd_time_ms_; }
  // The control byte of the last valid host PDU (new or repeated); 0 before the first.
  [[nodiscard]] std::uint8_t host_control() const noexcept { return host_control_; }
  [[nodiscard]] profisafe::FDeviceEvent last_event() const noexcept { return last_event_; }
  [[nodiscard]] profisafe::FDevice& device() noexcept { return device_; }
  [[nodiscard]] const profisafe::FDevice& device() const noexcept { return device_; }

 private:
  struct Placement {
    std::size_t module = 0;
    int slot = 0;
    std::size_t prm_offset = 0, input_offset = 0, output_offset = 0, pdu_size = 0;
  };
  FModuleDevice(profisafe::FDeviceConfig config, const Placement& placement);

  profisafe::FDeviceConfig config_;
  profisafe::FDevice device_;
  std::size_t module_ = 0;
  int slot_ = 0;
  std::size_t data_size_ = 0;
  std::size_t prm_offset_ = 0;
  std::size_t input_offset_ = 0;
  std::size_t output_offset_ = 0;
  std::size_t pdu_size_ = 0;
  std::array<std::uint8_t, profisafe::kMaxDataSize> f_inputs_{};
  std::array<std::uint8_t, profisafe::kMaxPduSize> sent_{};  // the PDU on the wire
  std::chrono::milliseconds hold_{0};
  std::optional<profisafe::TimePoint> held_until_;
  std::uint16_t wd_time_ms_ = 0;
  std::uint8_t host_control_ = 0;
  profisafe::FDeviceEvent last_event_ = profisafe::FDeviceEvent::kIgnored;
};

// The F-device's state as the harness API and the event stream name it: "waiting-for-parameters"
// (none yet), "parameter-fault" (the last F-parameters refused: diagnosis 64..71), "startup"
// (accepted, fail-safe values until the host's first valid PDU), "run", "fail-safe-values" (the
// host asks for them with activate_FV), "passivated" (a communication fault, CE_CRC or
// WD_timeout reported, fail-safe values) [IEC 61784-3-3 F-Device behaviour].
[[nodiscard]] std::string_view f_state_token(const profisafe::FDevice& device) noexcept;
// "V1" or "V2".
[[nodiscard]] std::string_view f_mode_token(const profisafe::FDevice& device) noexcept;

}  // namespace rs4sim::gsd
