#pragma once
// A DP slave described by its GSD ([PROFIBUS GSD spec]): the station of `rs4sim run --device
// generic --gsd FILE [--module NAME]...`, of a bus file and beside `rs4sim master`. Sans-I/O
// like its peers (dp/devices/generic_device.h): the edge reads the file and names the options
// (app/devices/gsd_station_file.h), the harness API is rpc/gsd_service.h.
//
// What the GSD declares, the station does:
//   * Ident_Number (Set_Prm with another one → Prm_Fault, [IEC 61158-6-3 Set_Prm]);
//   * Chk_Cfg = the chosen modules' Cfg bytes in slot order (anything else → Cfg_Fault,
//     [IEC 61158-6-3 Chk_Cfg/Get_Cfg]; with DPV1 Check_Cfg_Mode the same I/O lengths suffice);
//   * User_Prm_Data as gsd::configure lays it out: another length, or a parameter outside its
//     GSD range or list → Prm_Fault in the diagnosis (gsd::check_user_prm); a GSD that
//     defines no User_Prm_Data takes any (defines_no_user_prm);
//   * DPV1_Slave, C1/C2_Read_Write_supp and their Max_Data_Len, Fail_Safe, WD_Base_1ms_supp,
//     Sync/Freeze/Set_Slave_Add support, Max_Diag_Data_Len;
//   * the I/O lengths of the modules: the inputs are what the harness set (per module, zero at
//     start), the outputs what the master wrote;
//   * a PROFIsafe F-module is an F-device (gsd/f_device_module.h, V1 or V2 as its F-parameters
//     say): it checks its F-parameter block (a refused one → Prm_Fault and the standard
//     diagnosis 64..71 in a status block `05 81 slot 00 nn`), its output bytes are the host's
//     safety PDU, its input bytes the device's answer around the F-input data the harness set.
// The supported baud rates and MaxTsdr are checked by the entry against the run's rate and
// given to our master (GsdStationSpec::max_tsdr).
//
// The DPV1 record store and the alarm trigger record are the generic device's
// (dp/devices/generic_device.h).

#include "dp/devices/generic_device.h"
#include "dp/master/master_config.h"
#include "dp/slave/slave.h"
#include "gsd/config.h"
#include "gsd/error.h"
#include "gsd/f_device_module.h"
#include "gsd/model.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace rs4sim::gsd {

// One GSD station as configured: the parsed file, the chosen modules, the address.
struct GsdStationSpec {
  std::string file;  // as given (for messages and listings)
  std::shared_ptr<const Device> device;
  SlaveSetup setup;  // gsd::configure with the chosen modules, default parameters
  std::uint8_t address = 126;
  struct ModuleIo {
    std::string name;
    std::size_t input_offset = 0, input_len = 0;
    std::size_t output_offset = 0, output_len = 0;
    bool preset = false;  // placed by `Preset = 1` (place_modules)
  };
  std::vector<ModuleIo> modules;  // slot order
  // The F_Dest_Add of the F-modules' F-devices (their address switch, [IEC 61784-3-3
  // F-Parameters]); unset: the F_Dest_Add the configuration writes, so that the default
  // Set_Prm is accepted.
  std::optional<std::uint16_t> f_dest_add;
};

// The F_Dest_Add the F-device of slot index `module` has at power-up: --f-dest-add, else the one
// the configuration writes (0: no F-parameter block in that slot).
std::uint16_t configured_f_dest_add(const GsdStationSpec& spec, std::size_t module);

// The spec of the station at `address` with `setup` (gsd::configure of `device`): the chosen
// modules' I/O in slot order, each at its offset in the station's input and output images.
GsdStationSpec station_spec(std::string file, std::shared_ptr<const Device> device,
                            SlaveSetup setup, std::uint8_t address);

// Whether the GSD defines no User_Prm_Data at all: no User_Prm_Data_Len, User_Prm_Data or
// Ext_User_Prm_Data_* globally, none in any module, no F-parameters (a file cut down to its
// modules, as users' files sometimes are). Such a station has nothing to check the bytes
// against: it takes whatever User_Prm_Data the master sends and keeps it, as the device the
// file was cut from did (docs/decisions.md#gsd-undefined-user-prm). The one bound it checks is
// Max_User_Prm_Data_Len when the file gives it: unchecked_user_prm_fault says why a length is
// refused (empty: accepted).
bool defines_no_user_prm(const Device& device);
std::string unchecked_user_prm_fault(const Device& device, std::size_t length);

// A station's bytes as the harness's event stream and the master's report show them:
// lowercase hex, space-separated ("5a 11 22"; none: "").
std::string io_hex(std::span<const std::uint8_t> bytes);
// The GSD's Unit_Diag texts of device-related diagnosis `blocks`, with the standard's meaning of
// an F-device's diagnosis 64..71 the GSD names no text for (gsd::device_diag_texts).
std::vector<std::string> diagnosis_texts(const Device& device, std::span<const std::uint8_t> blocks);
// The same "; "-separated (none: "").
std::string diagnosis_text(const Device& device, std::span<const std::uint8_t> blocks);

// Our class 1 master's entry for the station, from the same GSD: Set_Prm (Lock_Req, WD_On, the
// GSD's ident and User_Prm_Data), Chk_Cfg, image lengths, C1 timeout. An error (the file
// named) when the Set_Prm does not encode (kPrmTooLong) or decode (kBadValue).
Result<dp::master::SlaveEntry> master_entry(const GsdStationSpec& spec,
                                            std::chrono::milliseconds watchdog);

class GsdApplication final : public dp::slave::SlaveApplication {
 public:
  explicit GsdApplication(const GsdStationSpec& spec);

  void on_attach(dp::slave::SlaveControl& control) override {
    control_ = &control;
    generic_.on_attach(control);
  }
  dp::slave::PrmVerdict check_parameters(const dp::pdu::SetPrm& prm, dp::TimePoint now) override;
  dp::slave::CfgVerdict check_config(std::span<const std::uint8_t> cfg, bool user_check,
                                     dp::TimePoint now) override {
    return generic_.check_config(cfg, user_check, now);
  }
  [[nodiscard]] std::span<const std::uint8_t> real_config() const override {
    return generic_.real_config();
  }
  void on_outputs(std::span<const std::uint8_t> outputs, dp::TimePoint now) override;
  void on_outputs_cleared(dp::slave::OutputClear why, dp::TimePoint now) override {
    generic_.on_outputs_cleared(why, now);
  }
  void read_inputs(std::span<std::uint8_t> inputs, dp::TimePoint now) override;
  void on_state_change(dp::slave::State from, dp::slave::State to, dp::slave::TransitionReason why,
                       dp::TimePoint now) override {
    generic_.on_state_change(from, to, why, now);
  }
  dp::slave::AcyclicResult on_acyclic(const dp::slave::AcyclicRequest& req,
                                      dp::TimePoint now) override {
    return generic_.on_acyclic(req, now);
  }
  void on_alarm_acknowledged(const dp::slave::AlarmAck& ack, dp::TimePoint now) override {
    generic_.on_alarm_acknowledged(ack, now);
  }

  // The module's inputs (slot index, 0-based): `bytes` must be exactly its input length, for an
  // F-module its F-input data (FModuleDevice::f_data_size). std::errc::invalid_argument
  // otherwise.
  std::error_code set_inputs(std::size_t module, std::span<const std::uint8_t> bytes);
  [[nodiscard]] std::span<const std::uint8_t> inputs() const { return inputs_; }
  [[nodiscard]] std::span<const std::uint8_t> outputs() const { return generic_.outputs(); }
  [[nodiscard]] std::uint64_t exchanges() const { return generic_.exchanges(); }
  // Why the last Set_Prm was refused (empty: accepted or none yet).
  [[nodiscard]] const std::string& prm_fault() const { return prm_fault_; }
  [[nodiscard]] std::span<const std::uint8_t> user_prm_data() const { return user_prm_; }
  // The harness API (rpc/gsd_service.h): Ext_Diag and the device-related diagnosis
  // blocks (errors as SlaveControl::set_device_diagnosis), a DPV1 alarm (errors as
  // GenericDevice::raise_alarm).
  std::error_code set_diagnosis(std::span<const std::uint8_t> blocks, bool ext_diag);
  std::error_code raise_alarm(std::uint8_t type, std::uint8_t slot,
                              std::span<const std::uint8_t> user_data) {
    return generic_.raise_alarm(type, slot, user_data);
  }
  [[nodiscard]] std::span<const std::uint8_t> diagnosis_blocks() const { return diag_; }
  [[nodiscard]] bool ext_diag() const { return ext_diag_; }
  // The F-devices of the station's F-modules, slot order (FModuleDevice::module() is the slot
  // index); an F-module whose F-data the drivers cannot serve stays plain I/O (docs/gsd.md).
  [[nodiscard]] std::vector<FModuleDevice>& f_modules() { return f_modules_; }
  [[nodiscard]] const std::vector<FModuleDevice>& f_modules() const { return f_modules_; }
  [[nodiscard]] FModuleDevice* f_module(std::size_t module);
  // Power-up of the application (the slave's own power-up is Slave::restart): no Set_Prm
  // taken, no diagnosis, each F-device without F-parameters; the inputs the harness set stay.
  void power_up();

 private:
  void check_f_parameters();

  const GsdStationSpec& spec_;
  dp::devices::GenericDevice generic_;
  dp::slave::SlaveControl* control_ = nullptr;
  std::vector<std::uint8_t> inputs_;
  std::vector<std::uint8_t> user_prm_;
  std::string prm_fault_;
  std::vector<std::uint8_t> diag_;
  bool ext_diag_ = false;
  std::vector<FModuleDevice> f_modules_;
  bool f_diag_ = false;  // diag_ holds an F-device's status block
};

class GsdStation final : public dp::Station {
 public:
  // Throws std::system_error for a slave configuration dp::slave refuses.
  explicit GsdStation(GsdStationSpec spec);
  GsdStation(const GsdStation&) = delete;
  GsdStation& operator=(const GsdStation&) = delete;

  [[nodiscard]] std::uint8_t address() const override { return slave_.address(); }
  void on_telegram(const dp::fdl::Telegram& t, dp::TimePoint now) override {
    if (online_) slave_.on_telegram(t, now);
  }
  void on_time(dp::TimePoint now) override { slave_.on_time(now); }
  [[nodiscard]] std::optional<dp::TimePoint> next_deadline() const override {
    return slave_.next_deadline();
  }
  std::optional<dp::fdl::Telegram> take_transmit() override { return slave_.take_transmit(); }
  const dp::fdl::Telegram* next_transmit(dp::fdl::Telegram& scratch) override {
    return slave_.next_transmit(scratch);
  }
  void on_malformed_frame(std::error_code why) override { slave_.on_malformed_frame(why); }
  [[nodiscard]] std::uint16_t min_tsdr_bits() const override { return slave_.min_tsdr_bits(); }

  [[nodiscard]] const GsdStationSpec& spec() const { return *spec_; }
  // Off the bus (the connector pulled): the station hears nothing and so answers nothing; its
  // watchdog runs on, as a powered station's does. Back on: it answers again.
  void set_online(bool online) noexcept { online_ = online; }
  [[nodiscard]] bool online() const noexcept { return online_; }
  [[nodiscard]] GsdApplication& application() { return app_; }
  [[nodiscard]] const GsdApplication& application() const { return app_; }
  [[nodiscard]] dp::slave::Slave& slave() { return slave_; }
  [[nodiscard]] const dp::slave::Slave& slave() const { return slave_; }
  // "GSD slave 5 (X.gse, ident 0x0B4E, modules "A", "B", cfg 33 51)"
  [[nodiscard]] std::string describe() const;
  // The address switch of the F-device in slot index `module` set to `dest_add` (its own
  // F_Dest_Add, [IEC 61784-3-3 F-Parameters]); a device reads it at power-up, so the station
  // powers up again (Wait_Prm: the master's next Set_Prm meets the new switch).
  // std::errc::invalid_argument: no F-device in that slot.
  std::error_code set_f_dest_add(std::size_t module, std::uint16_t dest_add);

 private:
  static dp::slave::Config slave_config(const GsdStationSpec& spec);

  std::unique_ptr<const GsdStationSpec> spec_;  // stable address for app_
  GsdApplication app_;
  dp::slave::Slave slave_;
  bool online_ = true;
};

}  // namespace rs4sim::gsd
