#include "rpc/diagnosis_service.h"

#include "rpc/diagnosis_view.h"
#include "rpc/service_support.h"

namespace rs4sim::rpc {

grpc::Status Rs4DiagnosticsService::GetDiagnosis(grpc::ServerContext*,
                                                 const v1::StationRequest* in,
                                                 v1::DiagnosisView* out) {
  return on_device(c_, in->address(), [&](rs4::device::Rs4Device& d, dp::TimePoint) {
    const auto du = d.slave().diagnosis();
    out->set_address(in->address());
    // The RS4 is a DP-V1 slave: its device-related blocks are alarm and status PDUs
    // [RS4 manual §5.3, §6.3].
    fill_diagnosis(std::span(du.data(), du.size()), true, rs4_diagnosis_texts, *out);
    return grpc::Status::OK;
  });
}

}  // namespace rs4sim::rpc
