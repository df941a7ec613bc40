#pragma once
// rs4sim.v1.Diagnostics (diagnosis.proto, docs/rpc.md "Diagnosis"): a station's Slave_Diag
// decoded (rpc/diagnosis_view.h), on the loop through the Executor. On an RS4 run: the RS4's
// answer with the RS4's texts.

#include "rpc/rs4_services.h"
#include "rs4sim/v1/diagnosis.grpc.pb.h"

namespace rs4sim::rpc {

class Rs4DiagnosticsService final : public v1::Diagnostics::Service {
 public:
  explicit Rs4DiagnosticsService(const Rs4Context& c) : c_(c) {}
  grpc::Status GetDiagnosis(grpc::ServerContext*, const v1::StationRequest* in,
                            v1::DiagnosisView* out) override;

 private:
  Rs4Context c_;
};

}  // namespace rs4sim::rpc
