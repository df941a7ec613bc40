#pragma once
// rs4sim.v1.Diagnostics (diagnosis.proto, docs/rpc.md "Diagnosis"): a station's Slave_Diag
// decoded (rpc/diagnosis_view.h), on the loop through the Executor. One service per run answers
// for each address: an RS4 with the RS4's texts, a GSD station with its GSD's texts and its
// modules' names.

#include "gsd/station/gsd_station.h"
#include "rpc/run_target.h"
#include "rs4sim/v1/diagnosis.grpc.pb.h"

#include <vector>

namespace rs4sim::rpc {

class DiagnosticsService final : public v1::Diagnostics::Service {
 public:
  // `gsd`: the run's GSD stations (distinct addresses, none of them an RS4 of `run`).
  explicit DiagnosticsService(const RunContext& run, std::vector<gsd::GsdStation*> gsd = {})
      : run_(run), gsd_(std::move(gsd)) {}
  grpc::Status GetDiagnosis(grpc::ServerContext*, const v1::StationRequest* in,
                            v1::DiagnosisView* out) override;

 private:
  RunContext run_;
  std::vector<gsd::GsdStation*> gsd_;
};

}  // namespace rs4sim::rpc
