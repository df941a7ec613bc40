// libFuzzer target: rpc::fill_diagnosis with the RS4's texts (rpc/diagnosis_view.h), the input as
// a Slave_Diag DU, read as DP-V1 and as DP-V0. Invariants: no crash or hang; the raw bytes are
// kept whole; an answer shorter than the standard part has no blocks and says why.
#include "rpc/diagnosis_view.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  for (const bool dpv1 : {true, false}) {
    rs4sim::v1::DiagnosisView view;
    rs4sim::rpc::fill_diagnosis(std::span(data, size), dpv1, rs4sim::rpc::rs4_diagnosis_texts, view);
    if (view.raw().size() != size) std::abort();
    if (size < 6 && (view.blocks_size() != 0 || view.error().empty())) std::abort();
  }
  return 0;
}
