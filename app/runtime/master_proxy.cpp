#include "app/runtime/master_proxy.h"

#include "app/runtime/master_report.h"
#include "app/runtime/progress_bar.h"
#include "rpc/archive_service.h"
#include "storage/sqlite_archive.h"  // default_archive_path

#include <algorithm>
#include <chrono>
#include <optional>
#include <variant>

namespace rs4sim::app {
storage::Timestamp wall_now() {
  return std::chrono::time_point_cast<std::chrono::milliseconds>(std::chrono::system_clock::now());
}

std::string master_archive_location(const std::string& given, bool simulated) {
  if (!given.empty()) return given;
  return simulated ? std::string(":memory:") : storage::default_archive_path().string();
}

proxy::RecordResult to_record_result(const dp::master::Dpv1Result& r) {
  if (!r.error) return proxy::RecordResult::success({r.data.begin(), r.data.end()});
  if (r.negative) {
    return proxy::RecordResult::negative(dp::pdu::to_wire(r.negative->error_code_1),
                                         r.negative->error_code_2);
  }
  // No response (a timeout, the slave not or no longer in data exchange): W#16#80C5
  // [docs/decisions.md#proxy-error-code-sfc].
  return proxy::RecordResult::no_response();
}

namespace {

std::string hex4(std::uint16_t v) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string s = "0x";
  for (int shift = 12; shift >= 0; shift -= 4) s += kDigits[(v >> shift) & 0xFU];
  return s;
}

// The read that repeats `first` to compare the two answers ([RS4 manual §5.3] adapter errors
// 0x2B2x; docs/proxy.md "Every read is repeated and compared"), if `first` is such a read.
std::optional<proxy::Step> compare_read_of(proxy::Step first) {
  using proxy::Step;
  switch (first) {
    case Step::kIdentify1: return Step::kIdentify2;
    case Step::kUpload1: return Step::kUpload2;
    case Step::kReidentify1: return Step::kReidentify2;
    case Step::kVerifyIdentify1: return Step::kVerifyIdentify2;
    case Step::kVerifyUpload1: return Step::kVerifyUpload2;
    default: return std::nullopt;
  }
}

}  // namespace

ProxyPlugin::ProxyPlugin(storage::ParameterArchive& archive, const ProxyPluginOptions& options)
    : archive_(archive),
      options_(options),
      scheduler_(archive, proxy::SchedulerConfig{options.bus, options.max_parallel, wall_now,
                                                 options.simulated,
                                                 !options.simulated || options.keep_proxy_state,
                                                 options.recording}),
      driver_(scheduler_, *this) {}

ServiceList ProxyPlugin::services(const ServiceContext& context) {
  feed_ = std::make_unique<rpc::ProxyFeed>();
  const dp::Clock& clock = context.clock;
  rpc::ProxySource source;
  source.bus = options_.bus;
  source.max_parallel = options_.max_parallel;
  source.status = [this] { return scheduler_.status(); };
  source.queue = [this] {
    return std::vector<std::uint8_t>(scheduler_.queue().begin(), scheduler_.queue().end());
  };
  source.now_ns = [&clock] {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(clock.now().time_since_epoch())
        .count();
  };
  archive_service_ = std::make_shared<rpc::ArchiveService>(archive_, context.executor, wall_now,
                                                           options_.archive_location);
  return {std::make_shared<rpc::ProxyService>(std::move(source), *feed_, context.executor),
          archive_service_};
}

void ProxyPlugin::stop_services() {
  if (feed_) feed_->close();
  if (archive_service_) archive_service_->close_streams();
}

void ProxyPlugin::publish_changes(dp::TimePoint now) {
  if (!feed_) return;
  const auto now_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(now.time_since_epoch()).count();
  for (const auto& s : scheduler_.status()) {
    auto& last = published_[s.address];
    if (last == s) continue;
    feed_->publish(s, options_.bus, now_ns);
    last = s;
  }
}

void ProxyPlugin::start(rs4::device::Rs4MasterStation& station, dp::TimePoint) {
  station_ = &station;
  for (const auto a : station.slave_addresses()) {
    scheduler_.add(a);
    station.set_proxy_enable(a, true);
    driver_.set_proxy_enable(a, true);
  }
}

void ProxyPlugin::on_event(const rs4::device::Rs4MasterEvent& e,
                           rs4::device::Rs4MasterStation& station, MasterReport& report,
                           dp::TimePoint now) {
  station_ = &station;
  if (const auto* in = std::get_if<rs4::device::InputByteChanged>(&e)) {
    driver_.on_input_byte(in->address, in->current);
  } else if (const auto* r = std::get_if<rs4::device::RecordResult>(&e)) {
    const auto it = pending_.find(r->id);
    if (it == pending_.end()) return;  // somebody else's DPV1 request
    const std::uint8_t address = it->second;
    pending_.erase(it);
    driver_.on_record_result(address, to_record_result(*r), now);
  } else if (std::holds_alternative<rs4::device::MasterCycle>(e)) {
    on_cycle(report, now);
  }
}

void ProxyPlugin::on_cycle(MasterReport& report, dp::TimePoint now) {
  while (!refused_.empty()) {
    const std::uint8_t address = refused_.front();
    refused_.pop_front();
    // refused by the master at once (the slave is not in data exchange): W#16#80C5
    driver_.on_record_result(address, proxy::RecordResult::no_response(), now);
  }
  driver_.poll(now);
  for (const auto a : scheduler_.addresses()) scheduler_.persist(a, now);
  report_changes(report, now);
  publish_changes(now);
}

void ProxyPlugin::report_changes(MasterReport& report, dp::TimePoint now) {
  for (const auto& s : scheduler_.status()) {
    auto& last = last_[s.address];
    const bool outputs_changed = !(last.outputs == s.outputs) || last.running != s.running;
    const bool step_changed = last.progress.step != s.progress.step;
    if (!outputs_changed && !step_changed) continue;
    // The console names a read once: its compare read (the same request again) is no retry
    // and no news unless it fails; the JSON lines keep every step.
    const auto compare = compare_read_of(last.progress.step);
    const bool quiet = !report.json() && !outputs_changed && compare == s.progress.step;
    if (!quiet) report_status(report, s, now);
    last = s;
  }
}

void ProxyPlugin::report_status(MasterReport& report, const proxy::StationStatus& s,
                                dp::TimePoint now) {
  const auto& o = s.outputs;
  std::string text = std::string(proxy::to_string(s.progress.step));
  if (compare_read_of(s.progress.step)) text += " (read twice, compared)";
  if (s.progress.bytes_total > 0) {
    text += " " + progress_bar(s.progress.bytes_done, s.progress.bytes_total) + " " +
            std::to_string(s.progress.bytes_done) + "/" + std::to_string(s.progress.bytes_total) +
            " bytes";
  }
  text += std::string(o.fb_busy ? ", FB_BUSY" : "") +
          (o.config_set_to_default ? ", CONFIG_SET_TO_DEFAULT" : "");
  if (o.error_number_fb != 0) {
    text += ", ERROR_NUMBER_FB " + hex4(o.error_number_fb) + ", ERROR_CODE_SFC " +
            hex4(o.error_code_sfc) + ", ERROR_NUMBER_RS4 " + std::to_string(o.error_number_rs4);
  }
  report.custom(now, s.address, "proxy", text,
                {{"step", std::string(proxy::to_string(s.progress.step))},
                 {"bytes_done", static_cast<std::int64_t>(s.progress.bytes_done)},
                 {"bytes_total", static_cast<std::int64_t>(s.progress.bytes_total)},
                 {"fb_busy", o.fb_busy},
                 {"config_set_to_default", o.config_set_to_default},
                 {"error_number_fb", static_cast<std::int64_t>(o.error_number_fb)},
                 {"error_code_sfc", static_cast<std::int64_t>(o.error_code_sfc)},
                 {"error_number_rs4", static_cast<std::int64_t>(o.error_number_rs4)}});
}

void ProxyPlugin::submit_write(std::uint8_t address, std::span<const std::uint8_t> record) {
  submitted(address, station_->write_record(address, record));
}

void ProxyPlugin::submit_read(std::uint8_t address, std::uint8_t length) {
  submitted(address, station_->read_record(address, length));
}

void ProxyPlugin::submitted(std::uint8_t address,
                            const boost::outcome_v2::std_result<dp::master::Dpv1RequestId>& id) {
  if (id) {
    pending_[id.value()] = address;
  } else {
    refused_.push_back(address);  // e.g. not in data exchange: a failed record next cycle
  }
}

}  // namespace rs4sim::app
