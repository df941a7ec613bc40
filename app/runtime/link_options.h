#pragma once
// The link of a run (`rs4sim run`, `rs4sim master`): which line, its port and rate, the UDP
// endpoints, --duration, --grpc and --capture. Parsed once (app/cli/link_cli.h); the runtime
// only ever sees the LinkKind.

#include "app/runtime/capture_option.h"
#include "app/runtime/grpc_cli.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rs4sim::app {

enum class LinkKind {
  kMemory,  // our master + the device on the in-memory bus, simulated time
  kPty,     // a pseudo-terminal pair; the first stdout line is the slave side's path
  kSerial,  // --port DEVICE at --baud (a real RS-485 adapter)
  kUdp,     // one telegram per datagram, --listen HOST:PORT, --peer HOST:PORT
};

// "memory", "pty", "serial", "udp" (as on the command line).
[[nodiscard]] std::string_view link_name(LinkKind kind) noexcept;
[[nodiscard]] std::optional<LinkKind> parse_link_kind(std::string_view name) noexcept;
// A line with the wall clock (pty, serial, udp).
[[nodiscard]] constexpr bool is_realtime(LinkKind kind) noexcept {
  return kind != LinkKind::kMemory;
}

struct LinkOptions {
  LinkKind link = LinkKind::kMemory;
  std::string port;              // serial
  std::string baud = "1.5M";     // serial / pty (a byte device: plain bit/s, its default rate)
  bool baud_given = false;       // --baud was on the command line
  std::string listen, peer;      // udp
  double duration = 0;           // seconds; 0 = until Ctrl-C (memory: the device's default)
  // The gRPC API (--grpc HOST:PORT and its TLS/token options, app/runtime/grpc_cli.h,
  // docs/rpc.md); empty = none. With --link memory the run then stays on the manual clock
  // and serves until Ctrl-C (--duration: wall seconds): time moves only through the SimTime
  // service.
  GrpcCliOptions grpc;
  // --capture FILE / --capture-linktype: every PROFIBUS telegram of the run into a pcap file
  // (docs/capture.md); a byte device's frames with their direction (line_capture.h), as
  // --capture-rs232 FILE the RS4's RS232 port's.
  CaptureOptions capture;
  // A real line (docs/serial.md; `rs4sim run` only): the master's slot time in µs (a reply
  // later than that after the request is not sent, counted as late), the loop thread's
  // SCHED_FIFO priority 1..99, and the end summary's turnaround as JSON lines.
  std::optional<std::int64_t> tsl_us;
  std::optional<int> rt_priority;
  bool json = false;
};

// Throws UsageError with the reason for a bad combination. `byte_device`: --baud is the
// device's plain bit rate (checked by the device entry), not a PROFIBUS rate.
void validate(const LinkOptions& link, bool byte_device = false);

}  // namespace rs4sim::app
