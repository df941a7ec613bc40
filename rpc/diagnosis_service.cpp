#include "rpc/diagnosis_service.h"

#include "rpc/diagnosis_view.h"
#include "rpc/service_support.h"

namespace rs4sim::rpc {

grpc::Status DiagnosticsService::GetDiagnosis(grpc::ServerContext*, const v1::StationRequest* in,
                                              v1::DiagnosisView* out) {
  const gsd::GsdStation* station = nullptr;
  for (const auto* s : gsd_) {
    if (s->address() == in->address()) station = s;
  }
  if (station != nullptr) {
    run_.executor.run([&] {
      const auto du = station->slave().diagnosis();
      const auto& spec = station->spec();
      out->set_address(in->address());
      // A DPV1_Slave's device-related blocks are alarm and status PDUs [PROFIBUS GSD spec
      // DPV1_Slave] [IEC 61158-6-3 Slave_Diag].
      fill_diagnosis(std::span(du.data(), du.size()), spec.device->dpv1.slave,
                     gsd_diagnosis_texts(spec), *out);
    });
    return grpc::Status::OK;
  }
  return on_device(run_, in->address(), [&](rs4::device::Rs4Device& d, dp::TimePoint) {
    const auto du = d.slave().diagnosis();
    out->set_address(in->address());
    // The RS4 is a DP-V1 slave: its device-related blocks are alarm and status PDUs
    // [RS4 manual §5.3, §6.3].
    fill_diagnosis(std::span(du.data(), du.size()), true, rs4_diagnosis_texts, *out);
    return grpc::Status::OK;
  });
}

}  // namespace rs4sim::rpc
