#pragma once
// Typed errors of the real-time transports (serial/pty, UDP), category "stream.link".
// These are configuration/OS errors at the edge; bad wire input is never an error here
// (it is dropped and counted by the runner on top: dp/link/counters.h, stream/byte_runner.h).

#include "codec/error_category.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

namespace rs4sim::stream {

enum class LinkError : std::uint8_t {
  kAdapterRefusedBaudRate = 1,  // the serial driver did not take the rate
  kAdapterRefusedFormat,        // the serial driver did not take the character format
  kNotATerminal,                // the device is no tty (tcgetattr failed)
  kOpenFailed,                  // open() of the device failed
  kPtyFailed,                   // posix_openpt/grantpt/unlockpt/ptsname failed
  kBadEndpoint,                 // "HOST:PORT" malformed or not resolvable
  kBindFailed,                  // UDP bind failed (port in use, …)
};

[[nodiscard]] std::string_view to_string(LinkError e) noexcept;
constexpr const char* error_category_name(LinkError) noexcept { return "stream.link"; }
inline std::error_code make_error_code(LinkError e) noexcept {
  return codec::make_error_code_of(e);
}

// Thrown by link constructors: the code plus the context (device path, rate, errno text).
class LinkException : public std::system_error {
 public:
  LinkException(LinkError e, const std::string& what)
      : std::system_error(make_error_code(e), what) {}
};

}  // namespace rs4sim::stream
