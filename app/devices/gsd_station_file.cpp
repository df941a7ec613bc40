#include "app/devices/gsd_station_file.h"

#include "app/runtime/usage_error.h"
#include "app/runtime/whole_file.h"
#include "dp/pdu/sap.h"
#include "dp/time/baud_rate.h"
#include "gsd/interp.h"
#include "gsd/syntax.h"

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

}  // namespace

GsdStationSpec load_gsd_station(const std::string& path, const std::vector<std::string>& modules,
                                int address, std::vector<std::string>* warnings) {
  if (address < 0 || address > dp::pdu::sap::kMaxSlaveAddress) {
    throw UsageError(path + ": address " + std::to_string(address) + " is outside 0.." +
                     std::to_string(dp::pdu::sap::kMaxSlaveAddress) +
                     " ([IEC 61158-4-3 addresses, SAPs])");
  }
  auto parsed = gsd::parse(read_text(path), path);
  if (!parsed) throw UsageError(parsed.error().what());
  auto device = std::make_shared<const gsd::Device>(std::move(parsed).value());
  if (warnings) {
    for (const auto& w : device->warnings) warnings->push_back(w.what());
  }
  auto setup = gsd::configure(*device, {modules, {}});
  if (!setup) throw UsageError(path + ": " + setup.error().what());
  return gsd::station_spec(path, std::move(device), std::move(setup).value(),
                           static_cast<std::uint8_t>(address));
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

std::uint16_t check_f_dest_add(const GsdStationSpec& spec, int value) {
  if (spec.setup.f_parameters.empty()) {
    throw UsageError(spec.file + ": --f-dest-add / \"f-dest-add\": no module of the station is "
                     "a PROFIsafe F-module");
  }
  for (const auto& [number, p] : spec.device->params) {
    if (!gsd::syntax::iequals(p.name, "F_Dest_Add") || p.accepts(value)) continue;
    throw UsageError(spec.file + ":" + std::to_string(p.line) + ": F_Dest_Add = " +
                     std::to_string(value) + " is outside the GSD's range " + p.range_text());
  }
  return static_cast<std::uint16_t>(value);
}

dp::master::SlaveEntry gsd_master_entry(const GsdStationSpec& spec,
                                        std::chrono::milliseconds watchdog) {
  auto entry = gsd::master_entry(spec, watchdog);
  if (!entry) throw UsageError(spec.file + ": " + entry.error().message);
  return std::move(entry).value();
}

}  // namespace rs4sim::app
