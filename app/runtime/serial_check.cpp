#include "app/runtime/serial_check.h"

#include "dp/fdl/decoder.h"
#include "dp/fdl/telegram.h"
#include "dp/link/profibus_line.h"
#include "dp/link/turnaround.h"
#include "stream/serial_adapter.h"
#include "stream/serial_settings.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ostream>

namespace rs4sim::app {

namespace {

using Clock = std::chrono::steady_clock;

// profirust's tested settings with CH341/FT232R adapters: 30 ms at 19.2k, 8 ms at 93.75k …
// 500k; the slower rates take the 19.2k setting, the faster ones (none tested) the 8 ms.
constexpr std::uint32_t kFastestTested = 500000;
double floor_ms(dp::BaudRate rate) { return dp::bits_per_second(rate) <= 45450 ? 30.0 : 8.0; }

std::string ms_text(double ms) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", ms);
  return b;
}

struct Collector final : dp::fdl::DecoderSink {
  std::vector<dp::fdl::Telegram> frames;
  void on_telegram(const dp::fdl::Telegram& t) override { frames.push_back(t); }
};

}  // namespace

std::vector<SlotTimeRow> slot_time_table(std::chrono::nanoseconds worst_turnaround) {
  std::vector<SlotTimeRow> rows;
  for (const dp::BaudRate rate : dp::kStandardBaudRates) {
    const double bps = dp::bits_per_second(rate);
    // Twice the worst turnaround, plus the reply's first character (11 bit times), which the
    // master must see start within TSL [IEC 61158-4-3 UART character].
    const double measured_ms =
        2.0 * static_cast<double>(worst_turnaround.count()) / 1e6 + 11.0 * 1e3 / bps;
    SlotTimeRow row{rate, std::nullopt, measured_ms, false,
                    dp::bits_per_second(rate) <= kFastestTested};
    if (floor_ms(rate) >= measured_ms) {
      row.ms = floor_ms(rate);
      row.floor = true;
    }
    const double bits = std::ceil(row.ms * bps / 1e3 - 1e-9);
    if (bits <= 16383) row.bits = static_cast<std::uint32_t>(bits);
    rows.push_back(row);
  }
  return rows;
}

std::optional<SlotTimeRow> recommended_rate(const std::vector<SlotTimeRow>& rows) {
  std::optional<SlotTimeRow> best;
  for (const SlotTimeRow& r : rows) {
    if (r.bits && r.tested &&
        (!best || dp::bits_per_second(r.rate) > dp::bits_per_second(best->rate)))
      best = r;
  }
  return best;
}

namespace {
const char* row_source(const SlotTimeRow& r) {
  if (!r.bits) return "not usable on this line (TSL is at most 16383 bit times)";
  if (!r.tested) {
    return r.floor ? "not advised: nothing tested above 500k (8 ms kept as the floor)"
                   : "not advised: nothing tested above 500k (measured)";
  }
  return r.floor ? "profirust's tested setting (above the measurement)"
                 : "measured: 2 x worst turnaround + 1 character";
}
}  // namespace

void print_slot_time_table(std::ostream& out, const std::vector<SlotTimeRow>& rows) {
  out << "slot time to enter (user-defined bus profile; retry limit 2-3):\n"
      << "  rate       TSL bit times  TSL ms    from\n";
  for (const SlotTimeRow& r : rows) {
    char line[160];
    const std::string bits = r.bits ? std::to_string(*r.bits) : "> 16383";
    std::snprintf(line, sizeof line, "  %-9s  %13s  %8s  %s\n", dp::to_string(r.rate).c_str(),
                  bits.c_str(), ms_text(r.ms).c_str(), row_source(r));
    out << line;
  }
  const auto best = recommended_rate(rows);
  if (!best) {
    out << "recommended: none; even 9.6k needs more than 16383 bit times with this line\n";
    return;
  }
  out << "recommended: " << dp::to_string(best->rate) << ", TSL " << *best->bits << " bit times ("
      << ms_text(best->ms)
      << " ms), retry limit 2-3: the fastest rate with a tested setting that this line "
         "meets; not 1.5M or faster (untested, and the slot time an engineering tool derives "
         "from the GSD there is one no PC meets)\n";
}

std::string nothing_answered_advice(bool pty, const std::string& port, const std::string& baud,
                                    int address) {
  const std::string head = "nothing answered on " + port + " at " + baud;
  if (pty) {
    return head +
           ": it is a pseudo-terminal, with no wire and no termination; nothing on its "
           "other end answered as station " +
           std::to_string(address) + ": start the slave first (`rs4sim run --address " +
           std::to_string(address) + " --link pty --baud " + baud +
           "` prints the path to give as --port) and check --address";
  }
  return head +
         ": check the wiring (A/B), the termination, the station's address (--address) "
         "and rate, or plug in a loopback";
}

namespace {

// The port opened and configured for the PROFIBUS line at `rate` (8E1), and what
// configure_serial and tune_adapter noted.
struct OpenPort {
  int fd = -1;
  stream::SerialSetup setup;
  std::vector<std::string> notes;

  OpenPort() = default;
  OpenPort(const OpenPort&) = delete;
  OpenPort& operator=(const OpenPort&) = delete;
  ~OpenPort() {
    if (fd >= 0) ::close(fd);
  }
  [[nodiscard]] stream::LogFn note() {
    return [this](const std::string& s) { notes.push_back(s); };
  }
};

// False (the reason on `err`) when the port does not open or take the line settings.
bool open_port(const SerialCheckOptions& o, dp::BaudRate rate, OpenPort& port, std::ostream& err) {
  port.fd = ::open(o.port.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (port.fd < 0) {
    err << "rs4sim: serial-check: " << o.port << ": " << std::strerror(errno) << std::endl;
    return false;
  }
  try {
    port.setup =
        stream::configure_serial(port.fd, dp::link::profibus_line(rate), o.port, port.note());
  } catch (const std::exception& e) {
    err << "rs4sim: serial-check: " << e.what() << std::endl;
    return false;
  }
  return true;
}

// The port, its adapter (tuned for low latency) and the rate the driver reports.
void print_port(const SerialCheckOptions& o, dp::BaudRate rate, OpenPort& port, std::ostream& out) {
  const std::string tty = stream::tty_name(port.fd);
  const bool other = !tty.empty() && "/dev/" + tty != o.port;
  out << "port " << o.port << (other ? " (/dev/" + tty + ")" : "") << "\n";
  if (port.setup.is_pty) {
    out << "  adapter: none, a pseudo-terminal (no line, no adapter latency)\n";
  } else {
    const auto a = stream::tune_adapter(port.fd, tty, port.note(), o.sysfs);
    out << "  driver: " << (a.driver.empty() ? "unknown (not in sysfs)" : a.driver) << "\n"
        << "  latency timer: "
        << (a.latency_timer_ms ? std::to_string(*a.latency_timer_ms) + " ms"
                               : "none (no USB serial)")
        << ", ASYNC_LOW_LATENCY " << (a.async_low_latency ? "on" : "off") << ", low latency "
        << (a.low_latency() ? "yes" : "NO") << "\n"
        << "  RS-485 mode (TIOCSRS485): " << (a.rs485 ? "on" : "not offered by the driver") << "\n";
  }
  out << "  rate: asked " << dp::bits_per_second(rate) << " bit/s, driver reports "
      << port.setup.actual_baud << " bit/s\n";
  for (const auto& n : port.notes) out << "  note: " << n << "\n";
}

// The FDL_Status request: SD1 DA SA FC=0x49 FCS ED [IEC 61158-4-3 frame formats].
std::vector<std::uint8_t> fdl_status_request(const SerialCheckOptions& o) {
  std::vector<std::uint8_t> request;
  dp::fdl::encode(
      dp::fdl::make_data_telegram(
          static_cast<std::uint8_t>(o.address), static_cast<std::uint8_t>(o.master),
          dp::fdl::FrameControl::request(dp::fdl::RequestFunction::kFdlStatus, false, false),
          std::nullopt, std::nullopt, {}),
      request);
  return request;
}

// What came back for one request before its timeout.
struct Answer {
  Clock::time_point sent{};
  std::optional<Clock::time_point> echo_at, reply_at;
  std::size_t reply_chars = 0;
};

// Reads until the station's reply or the timeout; our own request coming back is an echo.
void await_answer(int fd, const SerialCheckOptions& o, Answer& answer) {
  dp::fdl::Decoder decoder;
  Collector got;
  const auto deadline = answer.sent + std::chrono::milliseconds(o.timeout_ms);
  while (!answer.reply_at && Clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (::poll(&p, 1, static_cast<int>(std::max<std::int64_t>(left.count(), 1))) <= 0) continue;
    std::uint8_t buf[512];
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n <= 0) continue;
    const auto at = Clock::now();
    decoder.feed(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)), got);
    for (const auto& t : got.frames) {
      if (t.fc.is_request() && t.da == o.address && t.sa == o.master) {
        // Our own request: a loopback plug (or an echo).
        answer.echo_at = answer.echo_at.value_or(at);
      } else if (t.sa == o.address && !t.fc.is_request()) {
        answer.reply_at = at;
        answer.reply_chars = dp::fdl::encoded_size(t);
      }
    }
    got.frames.clear();
  }
}

// The requests' turnarounds beyond the wire time, and how each request ended.
struct Turnarounds {
  dp::link::TurnaroundStats stats;
  int replies = 0, echoes = 0, silent = 0;
};

// Sends o.count requests one after the other; false (the reason on `err`) when a write fails.
bool measure(const SerialCheckOptions& o, dp::BaudRate rate, const OpenPort& port,
             Turnarounds& result, std::ostream& err) {
  const auto request = fdl_status_request(o);
  const double bps = dp::bits_per_second(rate);
  // A pseudo-terminal has no wire: its bytes arrive at memory speed.
  const auto wire = [&](std::size_t chars) {
    if (port.setup.is_pty) return std::chrono::nanoseconds(0);
    return std::chrono::nanoseconds(
        static_cast<std::int64_t>(static_cast<double>(chars) * 11 * 1e9 / bps));
  };
  (void)tcflush(port.fd, TCIOFLUSH);
  for (int i = 0; i < o.count; ++i) {
    Answer answer;
    answer.sent = Clock::now();
    if (::write(port.fd, request.data(), request.size()) != static_cast<ssize_t>(request.size())) {
      err << "rs4sim: serial-check: write: " << std::strerror(errno) << std::endl;
      return false;
    }
    await_answer(port.fd, o, answer);
    if (answer.reply_at) {
      ++result.replies;
      result.stats.record(*answer.reply_at - answer.sent - wire(request.size()) -
                          wire(answer.reply_chars));
    } else if (answer.echo_at) {
      ++result.echoes;
      result.stats.record(*answer.echo_at - answer.sent - wire(request.size()));
    } else {
      ++result.silent;
    }
  }
  return true;
}

}  // namespace

int serial_check(const SerialCheckOptions& o, std::ostream& out, std::ostream& err) {
  const auto rate = dp::parse_baud_rate(o.baud);
  OpenPort port;
  if (!open_port(o, *rate, port, err)) return 1;
  print_port(o, *rate, port, out);
  Turnarounds t;
  if (!measure(o, *rate, port, t, err)) return 1;
  out << "turnaround: " << o.count << " FDL_Status requests to station " << o.address << ": "
      << t.replies << " replies, " << t.echoes << " loopback echoes, " << t.silent
      << " unanswered\n";
  if (t.stats.count() == 0) {
    err << "rs4sim: serial-check: "
        << nothing_answered_advice(port.setup.is_pty, o.port, o.baud, o.address) << std::endl;
    return 1;
  }
  const auto ms = [](std::int64_t ns) { return ms_text(static_cast<double>(ns) / 1e6); };
  out << "  beyond the wire time: p50 " << ms(t.stats.quantile_ns(0.5)) << " ms, p99 "
      << ms(t.stats.quantile_ns(0.99)) << " ms, max " << ms(t.stats.max_ns()) << " ms"
      << (t.replies > 0 ? " (both ends of the line)" : " (the adapter, there and back)") << "\n";
  print_slot_time_table(out, slot_time_table(std::chrono::nanoseconds(t.stats.max_ns())));
  out.flush();
  return 0;
}

}  // namespace rs4sim::app
