#pragma once
// The PROFIBUS character format on a serial line: 8 data bits, even parity, 1 stop bit at a
// standard rate ([IEC 61158-4-3 UART character] [IEC 61158-2 baud rates]), as the generic
// stream::LineSettings the transports (stream/serial_transport.h) configure a port with.

#include "dp/time/baud_rate.h"
#include "stream/line_settings.h"
#include "stream/serial_settings.h"

#include <string>

namespace rs4sim::dp::link {

[[nodiscard]] constexpr stream::LineSettings profibus_line(BaudRate baud) {
  return stream::LineSettings{bits_per_second(baud), 8, stream::Parity::kEven, 1};
}

// configure_serial() in the PROFIBUS format (throws stream::LinkException).
inline stream::SerialSetup configure_profibus_serial(int fd, BaudRate baud, const std::string& name,
                                                     const stream::LogFn& log) {
  return stream::configure_serial(fd, profibus_line(baud), name, log);
}

}  // namespace rs4sim::dp::link
