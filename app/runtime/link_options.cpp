#include "app/runtime/link_options.h"

#include "app/runtime/usage_error.h"
#include "dp/time/baud_rate.h"
#include "rpc/server.h"

#include <array>
#include <utility>

namespace rs4sim::app {

namespace {

constexpr std::array<std::pair<LinkKind, std::string_view>, 4> kNames{{
    {LinkKind::kMemory, "memory"},
    {LinkKind::kPty, "pty"},
    {LinkKind::kSerial, "serial"},
    {LinkKind::kUdp, "udp"},
}};

}  // namespace

std::string_view link_name(LinkKind kind) noexcept {
  for (const auto& [k, name] : kNames) {
    if (k == kind) return name;
  }
  return "?";
}

std::optional<LinkKind> parse_link_kind(std::string_view name) noexcept {
  for (const auto& [k, n] : kNames) {
    if (n == name) return k;
  }
  return std::nullopt;
}

void validate(const LinkOptions& l, bool byte_device) {
  if (l.duration < 0) throw UsageError("--duration must not be negative");
  // Every link refuses a rate that is not PROFIBUS's, the in-memory bus too: it models the
  // wire at that rate, and a typo must not run at some other one.
  if (!byte_device && !dp::parse_baud_rate(l.baud)) {
    throw UsageError("--baud " + l.baud + ": not a PROFIBUS rate; use one of " +
                     dp::standard_baud_rate_list());
  }
  if (!l.capture.rs232_file.empty() && (byte_device || !is_realtime(l.link))) {
    throw UsageError(
        "--capture-rs232 records the RS4's RS232 port, which a real-time run of the RS4 with "
        "--rs232 has");
  }
  if (l.link == LinkKind::kSerial && l.port.empty()) {
    throw UsageError("--link serial needs --port DEVICE (e.g. /dev/ttyUSB0)");
  }
  if (l.link == LinkKind::kUdp && (l.listen.empty() || l.peer.empty())) {
    throw UsageError("--link udp needs --listen HOST:PORT and --peer HOST:PORT");
  }
  if ((l.tsl_us || l.rt_priority) && !is_realtime(l.link)) {
    throw UsageError(std::string(l.tsl_us ? "--tsl" : "--rt-priority") +
                     " is for a real-time link (pty, serial, udp); the in-memory bus runs on "
                     "simulated time");
  }
  if (l.tsl_us) {
    if (byte_device)
      throw UsageError("--tsl is the PROFIBUS slot time; this device is not on PROFIBUS");
    // TSL is at most 16383 bit times [IEC 61158-4-3 bus parameters, timing]; at least 1 µs.
    const auto rate = *dp::parse_baud_rate(l.baud);
    const auto max_us = static_cast<std::int64_t>(16383.0 * 1e6 / dp::bits_per_second(rate));
    if (*l.tsl_us < 1 || *l.tsl_us > max_us) {
      throw UsageError("--tsl " + std::to_string(*l.tsl_us) + ": the slot time must be 1.." +
                       std::to_string(max_us) + " µs at " + l.baud + " (at most 16383 bit times)");
    }
  }
  if (l.rt_priority && (*l.rt_priority < 1 || *l.rt_priority > 99)) {
    throw UsageError("--rt-priority " + std::to_string(*l.rt_priority) +
                     ": SCHED_FIFO priorities are 1..99");
  }
  if (!l.grpc.empty()) grpc_server_options(l.grpc);  // unreadable files, missing TLS/token
}

}  // namespace rs4sim::app
