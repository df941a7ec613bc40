#include "app/devices/gsd_station.h"

#include "app/runtime/usage_error.h"
#include "app/runtime/whole_file.h"
#include "dp/pdu/sap.h"
#include "dp/pdu/set_prm.h"
#include "dp/time/baud_rate.h"
#include "gsd/dp_slave_config.h"
#include "gsd/interp.h"

#include <cstdio>

namespace rs4sim::app {
namespace {

std::string read_text(const std::string& path) {
  auto file = read_whole_file(path);
  if (!file) throw UsageError(path + ": cannot read the GSD file: " + file.error);
  return std::move(file.bytes);
}

const gsd::BaudRate* find_rate(const GsdStationSpec& spec, const std::string& baud) {
  const auto rate = dp::parse_baud_rate(baud);
  if (!rate) throw UsageError("--baud " + baud + " is not a PROFIBUS rate");
  return spec.device->find_baud(dp::bits_per_second(*rate));
}

std::string hex16(std::uint16_t v) {
  char b[8];
  std::snprintf(b, sizeof b, "0x%04X", v);
  return b;
}

}  // namespace

bool defines_no_user_prm(const gsd::Device& device) {
  if (device.user_prm.length != 0 || !device.params.empty()) return false;
  for (const auto& m : device.modules) {
    if (m.prm.length != 0 || m.f_prm) return false;
  }
  return true;
}

std::string unchecked_user_prm_fault(const gsd::Device& device, std::size_t length) {
  if (!device.max_user_prm_data_len || length <= *device.max_user_prm_data_len) return {};
  return "User_Prm_Data is " + std::to_string(length) + " bytes, the GSD allows " +
         std::to_string(*device.max_user_prm_data_len) + " (Max_User_Prm_Data_Len)";
}

GsdStationSpec load_gsd_station(const std::string& path, const std::vector<std::string>& modules,
                                int address, std::vector<std::string>* warnings) {
  if (address < 0 || address > dp::pdu::sap::kMaxSlaveAddress) {
    throw UsageError(path + ": address " + std::to_string(address) + " is outside 0.." +
                     std::to_string(dp::pdu::sap::kMaxSlaveAddress) +
                     " ([IEC 61158-4-3 addresses, SAPs])");
  }
  auto parsed = gsd::parse(read_text(path), path);
  if (!parsed) throw UsageError(parsed.error().what());
  GsdStationSpec spec;
  spec.file = path;
  spec.address = static_cast<std::uint8_t>(address);
  spec.device = std::make_shared<const gsd::Device>(std::move(parsed).value());
  if (warnings) {
    for (const auto& w : spec.device->warnings) warnings->push_back(w.what());
  }
  auto setup = gsd::configure(*spec.device, {modules, {}});
  if (!setup) throw UsageError(path + ": " + setup.error().what());
  spec.setup = std::move(setup).value();
  GsdStationSpec::ModuleIo io;
  for (const auto& placed : spec.setup.slots) {
    const gsd::Module* m = &spec.device->modules[placed.index];
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

void check_gsd_baud(const GsdStationSpec& spec, const std::string& baud) {
  const gsd::BaudRate* b = find_rate(spec, baud);
  if (b && b->supported) return;
  std::string list;
  for (const auto& r : spec.device->baud_rates) {
    if (r.supported) list += (list.empty() ? "" : ", ") + std::string(r.label);
  }
  throw UsageError(spec.file + ": the device does not support " + baud +
                   " bit/s (its GSD: " + list + ")");
}

std::optional<std::uint16_t> gsd_max_tsdr(const GsdStationSpec& spec, const std::string& baud) {
  const gsd::BaudRate* b = find_rate(spec, baud);
  if (!b) return std::nullopt;
  return b->max_tsdr;
}

dp::master::SlaveEntry gsd_master_entry(const GsdStationSpec& spec,
                                        std::chrono::milliseconds watchdog) {
  const gsd::SlaveSetup& c = spec.setup;
  dp::pdu::SetPrm fixed;
  fixed.station_status.lock_req = true;
  fixed.station_status.wd_on = true;
  const auto wd = dp::master::watchdog_factors(watchdog);
  fixed.wd_fact_1 = wd.f1;
  fixed.wd_fact_2 = wd.f2;
  fixed.min_tsdr = 11;
  fixed.ident_number = c.ident_number;
  dp::fdl::DataUnit du;
  if (!dp::pdu::encode_set_prm(fixed, du))
    throw UsageError(spec.file + ": Set_Prm does not encode");
  du.insert(du.end(), c.user_prm_data.begin(), c.user_prm_data.end());
  // A DPV1 slave reads bytes 7..9 as DPV1_Status ([IEC 61158-6-3 DPV1_Status]).
  auto prm =
      dp::pdu::decode_set_prm(std::span<const std::uint8_t>(du.data(), du.size()),
                              c.dpv1 ? dp::pdu::PrmLayout::kDpv1 : dp::pdu::PrmLayout::kDpv0);
  if (!prm) throw UsageError(spec.file + ": Set_Prm does not decode: " + prm.error().message());
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
      inputs_(spec.setup.input_len, 0) {}

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
    auto ok = gsd::check_user_prm(*spec_.device, spec_.setup, user_prm_);
    prm_fault_ = ok ? std::string() : ok.error().message;
  }
  // Prm_Fault in Station_Status_1 when refused.
  return prm_fault_.empty() ? dp::slave::PrmVerdict::kAccept : dp::slave::PrmVerdict::kPrmFault;
}

void GsdApplication::read_inputs(std::span<std::uint8_t> inputs, dp::TimePoint) {
  const std::size_t n = std::min(inputs.size(), inputs_.size());
  std::copy_n(inputs_.begin(), n, inputs.begin());
  std::fill(inputs.begin() + static_cast<std::ptrdiff_t>(n), inputs.end(), std::uint8_t{0});
}

std::error_code GsdApplication::set_inputs(std::size_t module,
                                           std::span<const std::uint8_t> bytes) {
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
  return gsd::dp_slave_config(*spec.device, spec.address);
}

GsdStation::GsdStation(GsdStationSpec spec)
    : spec_(std::make_unique<const GsdStationSpec>(std::move(spec))),
      app_(*spec_),
      slave_(slave_config(*spec_), app_) {
  slave_.set_wake_handler([this] { wake(); });
}

std::string GsdStation::describe() const {
  std::string modules;
  for (const auto& m : spec_->modules) {
    modules += (modules.empty() ? "\"" : ", \"") + m.name + (m.preset ? "\" (preset)" : "\"");
  }
  std::string cfg;
  char b[4];
  for (auto x : spec_->setup.cfg) {
    std::snprintf(b, sizeof b, "%02X", x);
    cfg += (cfg.empty() ? "" : " ") + std::string(b);
  }
  return "GSD slave " + std::to_string(spec_->address) + " (" + spec_->file + ", ident " +
         hex16(spec_->device->ident_number) + ", modules " + modules + ", cfg " + cfg + ")";
}

}  // namespace rs4sim::app
