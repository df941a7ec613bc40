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
  if (byte_device && !l.capture.file.empty()) {
    throw UsageError(
        "--capture writes PROFIBUS telegrams; this device's line carries none "
        "(record its bytes with e.g. socat -x or a serial sniffer)");
  }
  if (l.link == LinkKind::kSerial && l.port.empty()) {
    throw UsageError("--link serial needs --port DEVICE (e.g. /dev/ttyUSB0)");
  }
  if (l.link == LinkKind::kUdp && (l.listen.empty() || l.peer.empty())) {
    throw UsageError("--link udp needs --listen HOST:PORT and --peer HOST:PORT");
  }
  if (!l.grpc.empty()) grpc_server_options(l.grpc);  // unreadable files, missing TLS/token
}

}  // namespace rs4sim::app
