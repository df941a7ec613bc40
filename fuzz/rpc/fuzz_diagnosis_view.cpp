// libFuzzer target: rpc::fill_diagnosis with the RS4's texts and with a GSD station's
// (rpc/diagnosis_view.h: a small GSD with Unit_Diag, UnitDiagType and Channel_Diag texts, one
// module, and an F-module, so that an F-device's status block 64..71 gets the standard's
// meaning where the GSD has no text), the input as a Slave_Diag DU, read as DP-V1 and as DP-V0. Invariants: no crash or
// hang; the raw bytes are kept whole; an answer shorter than the standard part has no blocks
// and says why.
#include "gsd/interp.h"
#include "gsd/station/gsd_station.h"
#include "rpc/diagnosis_view.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

namespace {

const rs4sim::gsd::GsdStationSpec& gsd_spec() {
  static const rs4sim::gsd::GsdStationSpec spec = [] {
    auto device = rs4sim::gsd::parse(
        "#Profibus_DP\nIdent_Number = 0x1234\n12M_supp = 1\nMaxTsdr_12M = 800\n"
        "Unit_Diag_Bit(16) = \"a\"\nUnit_Diag_Area = 24-27\nValue(1) = \"b\"\n"
        "Unit_Diag_Area_End\nUnitDiagType = 129\nX_Unit_Diag_Bit(8) = \"c\"\n"
        "X_Unit_Diag_Area = 32-39\nX_Value(5) = \"d\"\nX_Unit_Diag_Area_End\nEndUnitDiagType\n"
        "Channel_Diag(16) = \"e\"\n",
        "fuzz.gsd");
    if (!device) std::abort();
    rs4sim::gsd::GsdStationSpec s;
    rs4sim::gsd::Device d = std::move(device).value();
    d.modules.emplace_back().f_prm.emplace();
    s.device = std::make_shared<const rs4sim::gsd::Device>(std::move(d));
    s.modules = {{.name = "m"}};
    return s;
  }();
  return spec;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  for (const bool dpv1 : {true, false}) {
    for (const auto& texts : {rs4sim::rpc::DiagnosisTexts(rs4sim::rpc::rs4_diagnosis_texts),
                              rs4sim::rpc::gsd_diagnosis_texts(gsd_spec())}) {
      rs4sim::v1::DiagnosisView view;
      rs4sim::rpc::fill_diagnosis(std::span(data, size), dpv1, texts, view);
      if (view.raw().size() != size) std::abort();
      if (size < 6 && (view.blocks_size() != 0 || view.error().empty())) std::abort();
    }
  }
  return 0;
}
