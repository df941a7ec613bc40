#include "rpc/bus_master_service.h"

#include "rpc/rs4_state.h"
#include "rpc/service_support.h"

#include <string>

namespace rs4sim::rpc {

void fill_bus_station(const rs4::device::Rs4MasterStation& station, std::uint8_t address,
                      v1::BusStation& out) {
  out.set_address(address);
  const auto view = station.view(address);
  if (!view) return;
  out.set_dp_state(dp::master::to_string(view->dp_state));
  out.set_dp_error(view->dp_error ? view->dp_error.message() : "");
  out.set_output_byte(view->output_byte);
  out.set_f_diagnosis(view->f_diagnosis);
  auto& plc = *out.mutable_plc();
  if (const auto* host = station.fhost(address)) fill_fhost(*host, view->input_byte, plc);
  plc.set_data_exchange(view->data_exchange());
  if (const auto status = station.master().slave_status(address)) {
    fill_dp_counters(status->counters, *plc.mutable_dp());
  }
}

grpc::Status BusMasterService::ListStations(grpc::ServerContext*, const v1::Empty*,
                                            v1::BusStationsResponse* out) {
  executor_.run([&] {
    for (const auto a : station_.slave_addresses()) {
      fill_bus_station(station_, a, *out->add_stations());
    }
    out->set_now_ns(to_ns(clock_.now()));
  });
  return grpc::Status::OK;
}

}  // namespace rs4sim::rpc
