// libFuzzer: any text (ASCII, UTF-8 or ISO 8859-1) → gsd::parse → (if it means something)
// gsd::configure (the slot list of gsd::place_modules: presets, SlotDefinition), the F-parameter
// defaults, the `gsd check` report, and the file's own bytes read as Ext_Diag_Data against its
// Unit_Diag texts. Seeds cover sub-families, Latin-1 text, skipped unknown keywords, presets,
// slot definitions and blocks nested in UnitDiagType.
// Must never crash, hang or leak; a successful configuration must be self-consistent.
#include "gsd/cfg.h"
#include "gsd/check_report.h"
#include "gsd/config.h"
#include "gsd/f_module.h"
#include "gsd/interp.h"
#include "gsd/unit_diag.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace {

void check(const rs4sim::gsd::SlaveSetup& c) {
  // Set_Prm DU ≤ 244 bytes = 7 standard bytes + user data ([IEC 61158-6-3 Set_Prm]).
  if (c.user_prm_data.size() > 237) __builtin_trap();
  if (c.cfg.empty()) return;
  auto layout = rs4sim::gsd::decode_cfg(c.cfg);
  if (!layout || layout.value().input_bytes != c.input_len ||
      layout.value().output_bytes != c.output_len) {
    __builtin_trap();
  }
  for (const auto& f : c.f_parameters) {
    if (f.offset + 10 > c.user_prm_data.size()) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto device = rs4sim::gsd::parse(text, "fuzz.gsd");
  if (!device) {
    if (device.error().what().empty()) __builtin_trap();
    return 0;
  }
  const auto& d = device.value();
  for (const auto& w : d.warnings) {
    if (w.line <= 0 || w.what().empty()) __builtin_trap();  // a warning names its line
  }
  if (auto c = rs4sim::gsd::configure(d, {})) check(c.value());
  rs4sim::gsd::ConfigRequest all;
  for (const auto& m : d.modules) {
    if (all.modules.size() < 4) all.modules.push_back(m.name);
  }
  for (const auto& [number, p] : d.params) {
    if (all.overrides.size() < 4) all.overrides.push_back({p.name, p.max});
  }
  if (auto c = rs4sim::gsd::configure(d, all)) check(c.value());
  for (const auto& m : d.modules) {
    (void)rs4sim::gsd::f_param_desc_crc(d, m);
    if (auto f = rs4sim::gsd::f_parameter_defaults(d, m); f && f.value().block.size() != 10) {
      __builtin_trap();
    }
    // Every F-module of a file that was read describes itself (checked while reading).
    if (rs4sim::gsd::is_f_module(m) && !rs4sim::gsd::describe_f_module(d, m)) __builtin_trap();
  }
  // The slot list: presets first, every slot a module of the file.
  if (auto placed = rs4sim::gsd::place_modules(d, all.modules)) {
    std::size_t presets = 0;
    for (const auto& p : placed.value()) {
      if (p.index >= d.modules.size()) __builtin_trap();
      if (p.preset && &p != &placed.value()[presets++]) __builtin_trap();
    }
  }
  if (d.modules.size() < 64 && rs4sim::gsd::check_report(d).empty()) __builtin_trap();
  // The texts come from the file: never more than it declares, its UnitDiagType blocks' included (a file starting with '#' reads
  // as a device-related block of 35 bytes, 0x23).
  const auto texts = rs4sim::gsd::unit_diag_texts(d.unit_diag, {data, size});
  const auto declared = [](const rs4sim::gsd::UnitDiagTexts& t) {
    return t.bits.size() + t.not_bits.size() + t.areas.size();
  };
  std::size_t most = declared(d.unit_diag);
  for (const auto& entry : d.unit_diag.types) most += declared(entry.second);
  if (texts.size() > most) __builtin_trap();
  return 0;
}
