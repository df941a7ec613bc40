// libFuzzer target: the METRON in standard line mode (metron::Device with the
// reporting scheduler and the report encoder). The first two bytes pick the format,
// separator, checksum, reporting mode, input type and period; then a script of request
// bytes, input toggles, scene changes and time steps. Invariants: no crash or hang; every
// report has Table 1's length and starts and ends with the framing characters [METRON
// manual "Standard line mode"]; two reports are never closer than Equation 1's t_send.
//
// Script: op byte, then its arguments
//   0 t      advance t ms      1 n ...  n bytes to the device (requests and garbage)
//   2 b      beam b on         3 b      beam b off      4 x  toggle the input (x ignored)
#include "fuzz/metron/metron_script.h"
#include "metron/standard_report.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace {

using namespace rs4sim;

metron::Options options_from(std::uint8_t a, std::uint8_t b) {
  metron::Options o;
  o.line_mode = metron::LineMode::kStandard;
  o.format = static_cast<metron::Format>(a % 3);
  o.separator = (a & 4U) != 0;
  o.checksum = (a & 8U) != 0;
  o.reporting_mode = static_cast<metron::ReportingMode>((a >> 4) % 5);
  o.input_type = static_cast<metron::InputType>(b % 7);
  constexpr std::array<int, 4> kPeriods{50, 100, 250, 1000};
  o.period = std::chrono::milliseconds(kPeriods[(b >> 3) % 4]);
  o.baud = (b & 0x80U) != 0 ? 1200 : 19200;
  if (o.input_type == metron::InputType::kStartStopLine ||
      o.input_type == metron::InputType::kStartStopAll)
    o.report = {metron::Measurement::kLongestRun};
  return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const auto o = options_from(data[0], data[1]);
  if (!o.validate().empty()) return 0;
  const metron::ReportFormat f{o.format, o.separator, o.checksum};
  const auto line = metron::line_settings(o);
  std::optional<stream::TimePoint> last;
  metron::fuzzing::Rig rig(
      metron::fuzzing::sent_to([&](std::span<const std::uint8_t> r, stream::TimePoint now) {
        if (r.size() != metron::report_length(o.report.size(), f)) std::abort();
        if (r.front() != o.wire.report_start || r.back() != o.wire.report_end) std::abort();
        if (last && now - *last < metron::send_time(r.size(), line)) std::abort();
        last = now;
      }),
      o);
  auto& d = rig.device();
  const std::uint8_t* p = data + 2;
  const std::uint8_t* end = data + size;
  while (p < end) {
    const auto op = static_cast<std::uint8_t>(*p++ % 5);
    if (metron::fuzzing::common_op(rig, op, p, end)) continue;
    const std::uint8_t arg = p < end ? *p++ : 0;
    switch (op) {
      case 2: d.set_beam(arg, true); break;
      case 3: d.set_beam(arg, false); break;
      default: d.set_input(!d.scene().input_high()); break;
    }
  }
  rig.run_for(std::chrono::milliseconds(100));
  return 0;
}
