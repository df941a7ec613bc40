// libFuzzer target: the METRON in standard line mode (metron::MetronDevice with the
// reporting scheduler and the report encoder). The first two bytes pick the format,
// separator, checksum, reporting mode, input type and period; then a script of request
// bytes, input toggles, scene changes and time steps. Invariants: no crash or hang; every
// report has Table 1's length and starts and ends with the framing characters [METRON
// manual "Standard line mode"]; two reports are never closer than Equation 1's t_send.
//
// Script: op byte, then its arguments
//   0 t      advance t ms      1 n ...  n bytes to the device (requests and garbage)
//   2 b      beam b on         3 b      beam b off      4  toggle the input
#include "metron/metron_device.h"
#include "metron/standard_report.h"
#include "stream/clock.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace {

using namespace rs4sim;
using namespace std::chrono_literals;

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

struct Harness {
  metron::Options options;
  stream::ManualClock clock;
  std::optional<metron::MetronDevice> device;
  std::optional<stream::TimePoint> last_report;

  void drain() {
    const metron::ReportFormat f{options.format, options.separator, options.checksum};
    while (auto r = device->take_transmit()) {
      const auto n = options.report.size();
      if (r->size() != metron::report_length(n, f)) std::abort();
      if (r->front() != options.wire.report_start || r->back() != options.wire.report_end)
        std::abort();
      if (last_report &&
          clock.now() - *last_report < metron::send_time(r->size(), device->line_settings()))
        std::abort();
      last_report = clock.now();
    }
  }
  void advance(stream::Duration d) {
    const auto target = clock.now() + d;
    for (int guard = 0; guard < 10000; ++guard) {
      const auto dl = device->next_deadline();
      if (!dl || *dl > target) break;
      if (*dl > clock.now()) clock.set(*dl);
      device->on_time(clock.now());
      drain();
    }
    clock.set(target);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  Harness h;
  h.options = options_from(data[0], data[1]);
  if (!h.options.validate().empty()) return 0;
  h.device.emplace(h.options);
  h.advance(0ms);
  const std::uint8_t* p = data + 2;
  const std::uint8_t* end = data + size;
  const auto arg = [&]() -> std::uint8_t { return p < end ? *p++ : 0; };
  while (p < end) {
    const std::uint8_t op = *p++;
    switch (op % 5) {
      case 0: h.advance(std::chrono::milliseconds(arg())); break;
      case 1: {
        const std::size_t n = std::min<std::size_t>(arg(), static_cast<std::size_t>(end - p));
        h.device->on_bytes(std::span<const std::uint8_t>(p, n), h.clock.now());
        p += n;
        break;
      }
      case 2: h.device->set_beam(arg(), true); break;
      case 3: h.device->set_beam(arg(), false); break;
      case 4: h.device->set_input(!h.device->scene().input_high()); break;
    }
    h.drain();
  }
  h.advance(500ms);
  return 0;
}
