#include "gsd/station/gsd_station.h"

#include "dp/pdu/set_prm.h"
#include "gsd/check_report.h"
#include "gsd/dp_slave_config.h"
#include "gsd/unit_diag.h"

#include <algorithm>
#include <cctype>

namespace rs4sim::gsd {
namespace {

Error set_prm_error(const GsdStationSpec& spec, GsdError code, std::string message) {
  Error e;
  e.code = code;
  e.file = spec.file;
  e.message = std::move(message);
  return e;
}

}  // namespace

bool defines_no_user_prm(const Device& device) {
  if (device.user_prm.length != 0 || !device.params.empty()) return false;
  for (const auto& m : device.modules) {
    if (m.prm.length != 0 || m.f_prm) return false;
  }
  return true;
}

std::string unchecked_user_prm_fault(const Device& device, std::size_t length) {
  if (!device.max_user_prm_data_len || length <= *device.max_user_prm_data_len) return {};
  return "User_Prm_Data is " + std::to_string(length) + " bytes, the GSD allows " +
         std::to_string(*device.max_user_prm_data_len) + " (Max_User_Prm_Data_Len)";
}

std::string io_hex(std::span<const std::uint8_t> bytes) {
  std::string s = hex_bytes({bytes.begin(), bytes.end()});  // "5A 11"
  std::transform(s.begin(), s.end(), s.begin(), [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  });
  return s;
}

std::vector<std::string> diagnosis_texts(const Device& device,
                                         std::span<const std::uint8_t> blocks) {
  const bool f_device = std::any_of(device.modules.begin(), device.modules.end(),
                                    [](const Module& m) { return m.f_prm.has_value(); });
  return device_diag_texts(device.unit_diag, f_device, blocks);
}

std::string diagnosis_text(const Device& device, std::span<const std::uint8_t> blocks) {
  std::string out;
  for (const auto& t : diagnosis_texts(device, blocks)) {
    out += (out.empty() ? "" : "; ") + t;
  }
  return out;
}

GsdStationSpec station_spec(std::string file, std::shared_ptr<const Device> device,
                            SlaveSetup setup, std::uint8_t address) {
  GsdStationSpec spec;
  spec.file = std::move(file);
  spec.address = address;
  spec.device = std::move(device);
  spec.setup = std::move(setup);
  GsdStationSpec::ModuleIo io;
  for (const auto& placed : spec.setup.slots) {
    const Module* m = &spec.device->modules[placed.index];
    io.name = m->name;
    io.input_len = m->input_len;
    io.output_len = m->output_len;
    io.preset = placed.preset;
    spec.modules.push_back(io);
    io.input_offset += m->input_len;
    io.output_offset += m->output_len;
  }
  return spec;
}

std::uint16_t configured_f_dest_add(const GsdStationSpec& spec, std::size_t module) {
  for (const auto& block : spec.setup.f_parameters) {
    if (block.module == module) return spec.f_dest_add.value_or(block.parameters.dest_add);
  }
  return 0;
}

Result<dp::master::SlaveEntry> master_entry(const GsdStationSpec& spec,
                                            std::chrono::milliseconds watchdog) {
  const SlaveSetup& c = spec.setup;
  dp::pdu::SetPrm fixed;
  fixed.station_status.lock_req = true;
  fixed.station_status.wd_on = true;
  const auto wd = dp::master::watchdog_factors(watchdog);
  fixed.wd_fact_1 = wd.f1;
  fixed.wd_fact_2 = wd.f2;
  fixed.min_tsdr = 11;
  fixed.ident_number = c.ident_number;
  dp::fdl::DataUnit du;
  if (!dp::pdu::encode_set_prm(fixed, du)) {
    return set_prm_error(spec, GsdError::kPrmTooLong, "Set_Prm does not encode");
  }
  du.insert(du.end(), c.user_prm_data.begin(), c.user_prm_data.end());
  // A DPV1 slave reads bytes 7..9 as DPV1_Status ([IEC 61158-6-3 DPV1_Status]).
  auto prm =
      dp::pdu::decode_set_prm(std::span<const std::uint8_t>(du.data(), du.size()),
                              c.dpv1 ? dp::pdu::PrmLayout::kDpv1 : dp::pdu::PrmLayout::kDpv0);
  if (!prm) {
    return set_prm_error(spec, GsdError::kBadValue,
                         "Set_Prm does not decode: " + prm.error().message());
  }
  dp::master::SlaveEntry m;
  m.address = spec.address;
  m.prm = prm.value();
  m.cfg.assign(c.cfg.begin(), c.cfg.end());
  m.input_length = c.input_len;
  m.output_length = c.output_len;
  if (spec.device->dpv1.c1_response_timeout != 0) {  // unit 10 ms ([PROFIBUS GSD spec DPV1])
    m.c1_response_timeout = std::chrono::milliseconds(10 * spec.device->dpv1.c1_response_timeout);
  }
  return m;
}

GsdApplication::GsdApplication(const GsdStationSpec& spec)
    : spec_(spec),
      generic_(dp::devices::GenericDeviceConfig{spec.setup.cfg}),
      inputs_(spec.setup.input_len, 0) {
  for (const auto& block : spec.setup.f_parameters) {
    const auto& io = spec.modules.at(block.module);
    auto f = FModuleDevice::make(*spec.device, spec.setup, block, io.input_offset,
                                 io.output_offset, configured_f_dest_add(spec, block.module));
    if (f) f_modules_.push_back(std::move(f).value());
  }
}

FModuleDevice* GsdApplication::f_module(std::size_t module) {
  for (auto& f : f_modules_) {
    if (f.module() == module) return &f;
  }
  return nullptr;
}

// [IEC 61784-3-3 F-Parameters]: each F-device checks its block; the first refused one gives
// Prm_Fault and its status block `05 81 slot 00 nn` with Ext_Diag.
void GsdApplication::check_f_parameters() {
  for (auto& f : f_modules_) {
    if (f.set_parameters(user_prm_).ok()) continue;
    const auto block = f.status_block();
    if (set_diagnosis(block, true)) diag_.assign(block.begin(), block.end());  // no slave yet
    f_diag_ = true;
    prm_fault_ = "F-module in slot " + std::to_string(spec_.setup.slots[f.module()].slot) +
                 ": diagnosis " + std::to_string(f.diagnosis()) + " (" +
                 f_diagnosis_text(spec_.device->unit_diag, f.diagnosis()) + ")";
    return;
  }
  if (f_diag_ && !set_diagnosis({}, false)) f_diag_ = false;
}

void GsdApplication::on_outputs(std::span<const std::uint8_t> outputs, dp::TimePoint now) {
  generic_.on_outputs(outputs, now);
  for (auto& f : f_modules_) f.on_outputs(outputs, now);
}

dp::slave::PrmVerdict GsdApplication::check_parameters(const dp::pdu::SetPrm& prm,
                                                       dp::TimePoint now) {
  (void)generic_.check_parameters(prm, now);
  // The whole User_Prm_Data as the GSD lays it out: DPV1_Status_1..3 first on a DPV1 slave.
  user_prm_.clear();
  if (prm.dpv1) {
    const auto s = prm.dpv1->to_bytes();
    user_prm_.assign(s.begin(), s.end());
  }
  user_prm_.insert(user_prm_.end(), prm.user_data.begin(), prm.user_data.end());
  if (defines_no_user_prm(*spec_.device)) {
    prm_fault_ = unchecked_user_prm_fault(*spec_.device, user_prm_.size());
  } else {
    auto ok = check_user_prm(*spec_.device, spec_.setup, user_prm_);
    prm_fault_ = ok ? std::string() : ok.error().message;
  }
  if (prm_fault_.empty()) check_f_parameters();
  // Prm_Fault in Station_Status_1 when refused.
  return prm_fault_.empty() ? dp::slave::PrmVerdict::kAccept : dp::slave::PrmVerdict::kPrmFault;
}

void GsdApplication::read_inputs(std::span<std::uint8_t> inputs, dp::TimePoint now) {
  const std::size_t n = std::min(inputs.size(), inputs_.size());
  std::copy_n(inputs_.begin(), n, inputs.begin());
  std::fill(inputs.begin() + static_cast<std::ptrdiff_t>(n), inputs.end(), std::uint8_t{0});
  for (auto& f : f_modules_) {
    f.device().on_time(now);  // the F-watchdog, checked at every poll
    f.write_inputs(inputs, now);
  }
}

void GsdApplication::power_up() {
  user_prm_.clear();
  prm_fault_.clear();
  diag_.clear();
  ext_diag_ = false;
  f_diag_ = false;
  for (auto& f : f_modules_) f.restart(f.dest_add());
}

std::error_code GsdApplication::set_inputs(std::size_t module,
                                           std::span<const std::uint8_t> bytes) {
  if (FModuleDevice* f = f_module(module)) {
    if (bytes.size() != f->f_data_size()) return std::make_error_code(std::errc::invalid_argument);
    f->set_f_inputs(bytes);
    return {};
  }
  if (module >= spec_.modules.size() || bytes.size() != spec_.modules[module].input_len) {
    return std::make_error_code(std::errc::invalid_argument);
  }
  std::copy(bytes.begin(), bytes.end(),
            inputs_.begin() + static_cast<std::ptrdiff_t>(spec_.modules[module].input_offset));
  return {};
}

std::error_code GsdApplication::set_diagnosis(std::span<const std::uint8_t> blocks, bool ext_diag) {
  if (control_ == nullptr) return std::make_error_code(std::errc::not_connected);
  if (auto e = control_->set_device_diagnosis(blocks, ext_diag, false)) return e;
  diag_.assign(blocks.begin(), blocks.end());
  ext_diag_ = ext_diag;
  return {};
}

dp::slave::Config GsdStation::slave_config(const GsdStationSpec& spec) {
  return dp_slave_config(*spec.device, spec.address);
}

GsdStation::GsdStation(GsdStationSpec spec)
    : spec_(std::make_unique<const GsdStationSpec>(std::move(spec))),
      app_(*spec_),
      slave_(slave_config(*spec_), app_) {
  slave_.set_wake_handler([this] { wake(); });
}

std::error_code GsdStation::set_f_dest_add(std::size_t module, std::uint16_t dest_add) {
  FModuleDevice* f = app_.f_module(module);
  if (f == nullptr) return std::make_error_code(std::errc::invalid_argument);
  slave_.restart(slave_.address());
  app_.power_up();
  f->restart(dest_add);
  return {};
}

std::string GsdStation::describe() const {
  std::string modules;
  for (const auto& m : spec_->modules) {
    modules += (modules.empty() ? "\"" : ", \"") + m.name + (m.preset ? "\" (preset)" : "\"");
  }
  return "GSD slave " + std::to_string(spec_->address) + " (" + spec_->file + ", ident " +
         hex16(spec_->device->ident_number) + ", modules " + modules + ", cfg " +
         hex_bytes(spec_->setup.cfg) + ")";
}

}  // namespace rs4sim::gsd
