#include "rs4/param_doc/contour_shapes.h"
#include "rs4/param_doc/parameter_document.h"
#include "rs4/report/json_writer.h"
#include "rs4/report/parameter_fields.h"

namespace rs4sim::rs4::param_doc {
namespace {

using report::JsonWriter;
using scanner::ParameterSet;

void write_device(JsonWriter& w, const scanner::Identity& id) {
  w.key("device").begin_object();
  w.field("device_type", id.device_type)
      .field("serial_number", id.serial_number)
      .field("firmware", report::firmware_text(id));
  w.end_object();
}

void write_options(JsonWriter& w, const ParameterSet& set) {
  w.field("response_time_ms", scanner::response_time(set).count());
  w.field("restart_mode", report::restart_mode_name(set.restart_mode));
  w.field("start_pair", set.start_pair);
  w.key("permitted").begin_object();
  for (std::uint8_t from = 1; from <= scanner::kFieldPairCount; ++from) {
    JsonWriter row;
    row.begin_array();
    for (const int to : report::permitted_targets(set, from)) row.value(std::int64_t{to});
    row.end_array();
    w.key(std::to_string(from)).raw(row.str());
  }
  w.end_object();
  JsonWriter sources;
  sources.begin_array();
  for (const auto& name : report::warning_output_names(set.warning_output)) sources.value(name);
  sources.end_array();
  w.key("warning_output").raw(sources.str());
  w.key("measurement").begin_object();
  w.field("resolution", set.measurement.resolution)
      .field("start", set.measurement.start)
      .field("stop", set.measurement.stop);
  w.end_object();
}

void write_contour(JsonWriter& w, std::string_view name, const scanner::Contour& contour) {
  w.key(name).begin_object().key("runs").begin_array();
  for (const Run& run : runs_of(contour)) {
    JsonWriter one;
    one.begin_object().field("from", run.first).field("to", run.last).field("mm", run.mm);
    w.raw(one.end_object().str());
  }
  w.end_array().end_object();
}

}  // namespace

std::string to_document(const ParameterSet& set) {
  JsonWriter w(2);
  w.begin_object();
  w.field("format", kDocumentFormat);
  write_device(w, set.identity);
  write_options(w, set);
  w.key("pairs").begin_object();
  for (std::size_t p = 0; p < scanner::kFieldPairCount; ++p) {
    w.key(std::to_string(p + 1)).begin_object();
    write_contour(w, "protective", set.pairs[p].protective_mm);
    write_contour(w, "warning", set.pairs[p].warning_mm);
    w.end_object();
  }
  w.end_object().end_object();
  return w.str() + "\n";
}

}  // namespace rs4sim::rs4::param_doc
