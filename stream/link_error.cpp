#include "stream/link_error.h"

namespace rs4sim::stream {

std::string_view to_string(LinkError e) noexcept {
  switch (e) {
    case LinkError::kAdapterRefusedBaudRate: return "the serial adapter refused the baud rate";
    case LinkError::kAdapterRefusedFormat: return "the serial adapter refused the character format";
    case LinkError::kNotATerminal: return "not a serial device (no termios)";
    case LinkError::kOpenFailed: return "cannot open the serial device";
    case LinkError::kPtyFailed: return "cannot create a pseudo-terminal";
    case LinkError::kBadEndpoint: return "bad HOST:PORT endpoint";
    case LinkError::kBindFailed: return "cannot bind the UDP socket";
  }
  return "unknown link error";
}

}  // namespace rs4sim::stream
