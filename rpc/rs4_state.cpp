#include "rpc/rs4_state.h"

#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/description.h"

#include <string>

namespace rs4sim::rpc {

void fill_input_bits(const rs4::adapter::InputBits& bits, v1::InputBits& out) {
  out.set_warning_field_violated(bits.warning_field);
  out.set_protective_field_violated(bits.protective_field);
  out.set_proxy_request(bits.proxy_request);
  out.set_rs232_active(bits.rs232_active);
  out.set_not_operational(bits.not_operational);
  out.set_error(bits.error);
  out.set_warning_output_active(bits.warning_output_active);
  out.set_ossd(bits.ossd);
}

void fill_dp_counters(const dp::master::PollCounters& c, v1::DpCounters& out) {
  out.set_requests(c.requests);
  out.set_repeats(c.retries);
  out.set_no_answer(c.no_answer);
  out.set_lost(c.left_data_exchange);
  out.set_syncs(c.entered_data_exchange);
  out.set_illegal(c.invalid_responses);
  out.set_negative(c.negative_replies);
  out.set_data_exchanges(c.data_exchanges);
  out.set_diag_reads(c.diag_reads);
}

void fill_fhost(const profisafe::FHost& host, std::uint8_t plc_input_byte, v1::PlcView& out) {
  const auto& n = host.counters();
  out.set_present(true);
  out.set_fhost_state(std::string(profisafe::to_token(host.state())));
  out.set_input_byte(plc_input_byte);
  fill_input_bits(rs4::adapter::decode_input_byte(plc_input_byte), *out.mutable_input());
  out.set_crc_errors(n.crc_errors);
  out.set_number_errors(n.number_errors);
  out.set_watchdog_timeouts(n.watchdog_timeouts);
  out.set_passivations(n.passivations);
  out.set_reintegrations(n.reintegrations);
}

void fill_state(const rs4::device::Rs4Device& device, std::uint8_t address, dp::TimePoint now,
                v1::DeviceState& out) {
  const auto view = device.adapter().view();
  const auto status = device.scanner().status();
  out.set_address(address);
  out.set_powered(device.powered());
  out.set_led(std::string(rs4::adapter::to_token(view.led)));
  out.set_led_lit(device.adapter().led_lit(now));
  const auto leds = device.scanner().leds();
  out.set_led3_red(leds.led3_red);
  out.set_led5_yellow_blinking(leds.led5_yellow_blinking);
  out.set_restart_button_held(device.adapter().restart_button());
  out.set_rs4_state(rs4::scanner::to_string(status.state));
  out.set_fdevice_state(std::string(profisafe::to_token(view.fdevice)));
  out.set_proxy_phase(std::string(rs4::adapter::to_token(view.proxy)));
  out.set_connected(view.connected);
  out.set_pc_adapter_attached(view.pc_adapter_attached);
  out.set_input_byte(view.input_byte);
  fill_input_bits(view.input, *out.mutable_input());
  out.set_output_byte(view.output_byte);
  auto* o = out.mutable_output();
  o->set_field_pair(view.output.field_pair);
  o->set_restart(view.output.restart);
  o->set_proxy_enable(view.output.proxy_enable);
  out.set_input_pdu(std::string(view.input_pdu.begin(), view.input_pdu.end()));
  out.set_output_pdu(std::string(view.output_pdu.begin(), view.output_pdu.end()));
  out.set_ossd(status.ossd);
  out.set_contamination_percent(status.contamination_percent);
  out.set_active_field_pair(status.first_pair);
  for (const auto& f : stream::faults_present(rs4::device::description(), device)) {
    out.add_faults_present(f);
  }
  out.set_scan_counter(status.scan_counter);
  out.set_f_dest_add(view.f_dest_add);
  out.set_now_ns(
      std::chrono::duration_cast<std::chrono::nanoseconds>(now.time_since_epoch()).count());
}

void fill_contour(const rs4::device::Rs4Device& device, v1::Contour& out) {
  const auto& scan = device.scanner().last_scan();
  out.set_scan_number(scan.scan_number);
  for (const auto mm : scan.contour) out.add_mm(mm);
}

void fill_link_timing(const dp::link::TurnaroundStats& stats,
                      std::optional<std::int64_t> slot_time_us, v1::LinkTiming& out) {
  using dp::link::TurnaroundStats;
  const auto u = [](std::int64_t ns) { return static_cast<std::uint64_t>(ns < 0 ? 0 : ns); };
  out.set_present(true);
  out.set_replies(stats.count());
  out.set_late(stats.late());
  out.set_slot_time_us(slot_time_us ? u(*slot_time_us) : 0U);
  out.set_p50_ns(u(stats.quantile_ns(0.5)));
  out.set_p99_ns(u(stats.quantile_ns(0.99)));
  out.set_max_ns(u(stats.max_ns()));
  out.set_mean_ns(u(stats.mean_ns()));
  for (std::size_t i = 0; i < TurnaroundStats::kBuckets; ++i) {
    if (stats.buckets()[i] == 0) continue;
    auto* b = out.add_histogram();
    b->set_upper_ns(i + 1 == TurnaroundStats::kBuckets ? 0U
                                                       : u(TurnaroundStats::bucket_upper_ns(i)));
    b->set_count(stats.buckets()[i]);
  }
}

}  // namespace rs4sim::rpc
