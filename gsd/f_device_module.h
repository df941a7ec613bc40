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

#include "gsd/config.h"
#include "gsd/f_module.h"
#include "profisafe/f_device.h"

#include <array>
#include <cstdint>
#include <span>
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
  // The module's part of the station's input image: the device's PDU.
  void write_inputs(std::span<std::uint8_t> inputs);
  // The device's F-input data (what a real device's sensors read); size = f_data_size().
  void set_f_inputs(std::span<const std::uint8_t> data) { device_.set_input(data); }
  // The host's F-output data as the device delivers them (0 while fail-safe).
  [[nodiscard]] std::span<const std::uint8_t> f_outputs() const noexcept {
    return device_.output();
  }
  [[nodiscard]] std::size_t f_data_size() const noexcept { return data_size_; }
  [[nodiscard]] std::size_t module() const noexcept { return module_; }
  [[nodiscard]] profisafe::FDevice& device() noexcept { return device_; }
  [[nodiscard]] const profisafe::FDevice& device() const noexcept { return device_; }

 private:
  struct Placement {
    std::size_t module = 0;
    int slot = 0;
    std::size_t prm_offset = 0, input_offset = 0, output_offset = 0, pdu_size = 0;
  };
  FModuleDevice(profisafe::FDeviceConfig config, const Placement& placement);

  profisafe::FDevice device_;
  std::size_t module_ = 0;
  int slot_ = 0;
  std::size_t data_size_ = 0;
  std::size_t prm_offset_ = 0;
  std::size_t input_offset_ = 0;
  std::size_t output_offset_ = 0;
  std::size_t pdu_size_ = 0;
};

}  // namespace rs4sim::gsd
