#include "dp/link/link_error.h"

namespace rs4sim::dp::link {

namespace {
class Category final : public std::error_category {
 public:
  const char* name() const noexcept override { return "dp.link"; }
  std::string message(int value) const override {
    switch (static_cast<LinkError>(value)) {
      case LinkError::kUnsupportedBaudRate: return "not a standard PROFIBUS baud rate";
      case LinkError::kAdapterRefusedBaudRate: return "the serial adapter refused the baud rate";
      case LinkError::kAdapterRefusedFormat: return "the serial adapter refused 8E1 framing";
      case LinkError::kNotATerminal: return "not a serial device (no termios)";
      case LinkError::kOpenFailed: return "cannot open the serial device";
      case LinkError::kPtyFailed: return "cannot create a pseudo-terminal";
      case LinkError::kBadEndpoint: return "bad HOST:PORT endpoint";
      case LinkError::kBindFailed: return "cannot bind the UDP socket";
    }
    return "unknown link error";
  }
};
}  // namespace

const std::error_category& link_category() noexcept {
  static const Category category;
  return category;
}

std::error_code make_error_code(LinkError e) noexcept {
  return {static_cast<int>(e), link_category()};
}

}  // namespace rs4sim::dp::link
