#include "app/runtime/master_report.h"

#include "dp/master/master_error.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/report/json_writer.h"
#include "rs4/safety/diagnosis.h"

#include <cstdio>
#include <ostream>
#include <type_traits>

namespace rs4sim::app {
namespace {

namespace device = rs4::device;
using rs4::report::json_quote;
using Fields = std::vector<ReportField>;

const char* diagnosis_text(std::uint8_t number) {
  using rs4::safety::FDiagnosis;
  for (const FDiagnosis d :
       {FDiagnosis::kNone, FDiagnosis::kInternalDestAdd, FDiagnosis::kWrongDestAdd,
        FDiagnosis::kWrongSourceAdd, FDiagnosis::kWrongWdTime, FDiagnosis::kWrongSil,
        FDiagnosis::kWrongCrcLength, FDiagnosis::kWrongBlockIdOrParVersion,
        FDiagnosis::kWrongCrc1}) {
    if (static_cast<std::uint8_t>(d) == number) return rs4::safety::to_string(d);
  }
  return "unknown";
}

std::string code_text(std::error_code ec) {
  return std::string(ec.category().name()) + ":" + std::to_string(ec.value());
}

std::string hex_byte(std::uint8_t b) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", b);
  return buf;
}

Fields input_fields(const device::InputByteChanged& e) {
  const auto bits = rs4::adapter::decode_input_byte(e.current);
  return {{"byte", std::int64_t{e.current}},
          {"hex", hex_byte(e.current)},
          {"previous", std::int64_t{e.previous}},
          {"ossd", bits.ossd},
          {"warning_output_active", bits.warning_output_active},
          {"error", bits.error},
          {"not_operational", bits.not_operational},
          {"rs232_active", bits.rs232_active},
          {"proxy_request", bits.proxy_request},
          {"protective_field", bits.protective_field},
          {"warning_field", bits.warning_field}};
}

Fields record_fields(const device::RecordResult& r) {
  const bool read = r.operation == dp::master::Dpv1Operation::kRead;
  Fields f{{"id", std::int64_t{r.id}},
           {"operation", std::string(read ? "read" : "write")},
           {"slot", std::int64_t{r.slot}},
           {"index", std::int64_t{r.index}},
           {"ok", !r.error}};
  if (r.error) {
    f.push_back({"error", r.error.message()});
    f.push_back({"error_code", code_text(r.error)});
  }
  f.push_back({"length", std::int64_t(read ? r.data.size() : r.length)});
  return f;
}

// The console's view of one RS4, without the time.
std::string console_text(const device::Rs4SlaveView& v) {
  std::string s = "RS4 " + std::to_string(v.address) + ": DP ";
  s += v.data_exchange() ? "data exchange" : "start-up";
  if (!v.data_exchange() && v.dp_error) s += " (" + v.dp_error.message() + ")";
  s += ", PROFIsafe " + std::string(profisafe::to_string(v.safety));
  if (v.f_diagnosis != 0) {
    s += ", diagnosis " + std::to_string(v.f_diagnosis) + " " + diagnosis_text(v.f_diagnosis);
  }
  const auto bits = rs4::adapter::decode_input_byte(v.input_byte);
  s += std::string(", OSSD ") + (bits.ossd ? "1" : "0");
  s += std::string(", Proxy-Request ") + (bits.proxy_request ? "1" : "0");
  return s;
}

}  // namespace

MasterReport::MasterReport(std::ostream& out, bool json, dp::TimePoint start)
    : out_(out), json_(json), start_(start) {}

std::string MasterReport::seconds(dp::TimePoint now) const {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now - start_).count();
  char buf[32];
  std::snprintf(buf, sizeof buf, "%lld.%03lld", static_cast<long long>(ms / 1000),
                static_cast<long long>(ms % 1000));
  return buf;
}

void MasterReport::json_line(dp::TimePoint now, std::uint8_t address, std::string_view event,
                             const Fields& fields) const {
  out_ << "{\"t\":" << seconds(now) << ",\"station\":" << int(address)
       << ",\"event\":" << json_quote(event);
  for (const auto& f : fields) {
    out_ << "," << json_quote(f.name) << ":";
    std::visit(
        [this](const auto& v) {
          using V = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<V, bool>) {
            out_ << (v ? "true" : "false");
          } else if constexpr (std::is_same_v<V, std::string>) {
            out_ << json_quote(v);
          } else if constexpr (std::is_same_v<V, std::vector<std::int64_t>>) {
            out_ << "[";
            for (std::size_t i = 0; i < v.size(); ++i) out_ << (i == 0 ? "" : ",") << v[i];
            out_ << "]";
          } else {
            out_ << v;
          }
        },
        f.value);
  }
  out_ << "}" << std::endl;
}

void MasterReport::started(const device::Rs4MasterStation& station, std::string_view link) const {
  std::string list;
  std::vector<std::int64_t> addresses;
  for (const auto a : station.slave_addresses()) {
    list += (list.empty() ? "" : ",") + std::to_string(a);
    addresses.push_back(a);
  }
  if (json_) {
    json_line(start_, station.address(), "start",
              {{"link", std::string(link)}, {"rs4", addresses}});
    return;
  }
  out_ << "master " << int(station.address()) << " on " << link;
  if (!list.empty()) out_ << ", RS4 at " << list;
  out_ << std::endl;
}

void MasterReport::json_event(const device::Rs4MasterEvent& e, dp::TimePoint now) const {
  if (const auto* dp_state = std::get_if<device::DpStateChanged>(&e)) {
    Fields f{{"state", std::string(dp::master::to_string(dp_state->state))},
             {"data_exchange", dp_state->data_exchange()}};
    if (dp_state->reason) {
      f.push_back({"reason", dp_state->reason.message()});
      f.push_back({"reason_code", code_text(dp_state->reason)});
    }
    json_line(now, dp_state->address, "dp", f);
  } else if (const auto* safety = std::get_if<device::SafetyStateChanged>(&e)) {
    json_line(now, safety->address, "profisafe",
              {{"state", std::string(profisafe::to_string(safety->state))}});
  } else if (const auto* diag = std::get_if<device::FDiagnosisChanged>(&e)) {
    json_line(now, diag->address, "f_diagnosis",
              {{"number", std::int64_t{diag->number}},
               {"text", std::string(diagnosis_text(diag->number))}});
  } else if (const auto* input = std::get_if<device::InputByteChanged>(&e)) {
    json_line(now, input->address, "input", input_fields(*input));
  } else if (const auto* record = std::get_if<device::RecordResult>(&e)) {
    json_line(now, record->address, "record", record_fields(*record));
  }
}

void MasterReport::explain_lost_slaves(unsigned retries, std::string hint) {
  retries_ = retries;
  lost_hint_ = std::move(hint);
}

void MasterReport::note_dp_state(const device::DpStateChanged& e, dp::TimePoint now) {
  bool& was = in_data_exchange_[e.address];
  // [IEC 61158-6-3 slave supervision]: no reply within TSL, then max_retry_limit retries.
  const bool lost = was && !e.data_exchange() &&
                    e.reason == dp::master::make_error_code(dp::master::MasterError::kNoAnswer);
  was = e.data_exchange();
  if (!lost) return;
  const std::string retries = std::to_string(retries_) + (retries_ == 1 ? " retry" : " retries");
  if (json_) {
    json_line(now, e.address, "lost", {{"retries", std::int64_t{retries_}}, {"hint", lost_hint_}});
    return;
  }
  out_ << seconds(now) << " s  RS4 " << int(e.address) << " lost: no reply after " << retries
       << (lost_hint_.empty() ? "" : "; " + lost_hint_) << std::endl;
}

void MasterReport::events(const std::vector<device::Rs4MasterEvent>& events,
                          const device::Rs4MasterStation& station, dp::TimePoint now) {
  for (const auto& e : events) {
    if (const auto* dp_state = std::get_if<device::DpStateChanged>(&e))
      note_dp_state(*dp_state, now);
  }
  if (json_) {
    for (const auto& e : events) json_event(e, now);
    return;
  }
  for (const auto a : station.slave_addresses()) {
    if (const auto v = station.view(a)) console_line(*v, now);
  }
}

void MasterReport::console_line(const device::Rs4SlaveView& v, dp::TimePoint now) {
  std::string text = console_text(v);
  auto& shown = shown_[v.address];
  if (text == shown) return;
  out_ << seconds(now) << " s  " << text << " (input " << hex_byte(v.input_byte) << ")"
       << std::endl;
  shown = std::move(text);
}

void MasterReport::custom(dp::TimePoint now, std::uint8_t address, std::string_view event,
                          std::string_view text, const Fields& fields) const {
  custom(now, address, "RS4", event, text, fields);
}

void MasterReport::custom(dp::TimePoint now, std::uint8_t address, std::string_view label,
                          std::string_view event, std::string_view text, const Fields& fields) const {
  if (json_) {
    json_line(now, address, event, fields);
    return;
  }
  out_ << seconds(now) << " s  " << label << " " << int(address) << ": " << text << std::endl;
}

void MasterReport::stopped(const device::Rs4MasterStation& station, dp::TimePoint now) const {
  for (const auto a : station.slave_addresses()) {
    const auto v = station.view(a);
    if (!v) continue;
    if (json_) {
      json_line(now, a, "stop",
                {{"dp", std::string(dp::master::to_string(v->dp_state))},
                 {"data_exchange", v->data_exchange()},
                 {"profisafe", std::string(profisafe::to_string(v->safety))},
                 {"f_diagnosis", std::int64_t{v->f_diagnosis}},
                 {"input", std::int64_t{v->input_byte}},
                 {"output", std::int64_t{v->output_byte}}});
    } else {
      out_ << seconds(now) << " s  end: " << console_text(*v) << " (input "
           << hex_byte(v->input_byte) << ", output " << hex_byte(v->output_byte) << ")"
           << std::endl;
    }
  }
}

}  // namespace rs4sim::app
