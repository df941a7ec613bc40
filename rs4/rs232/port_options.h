#pragma once
// Settings of the RS4's RS232 port (simulation settings, not RS4 parameters): what the app
// entry parses `--rs232 …@BAUD` and `--pc-adapter` into ([docs/rs232.md]).

#include "rs4/rs232/rs232_codes.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace rs4sim::rs4::rs232 {

struct PortOptions {
  std::uint32_t baud = kDefaultBaud;  // one of kBaudRates; 8N1 always
  bool stream_on_attach = true;       // continuous 0x23 from the moment the port opens
  std::size_t max_body = 2048;        // longer frames are dropped (kFrameTooLong), silently
  // Accepted while both user passwords of the set are empty (the factory state).
  std::array<std::uint8_t, 8> factory_password = kFactoryPassword;
  // nullopt when valid, else "baud 1234 is not one of 4800, 9600, …".
  [[nodiscard]] std::optional<std::string> validate() const;
};

}  // namespace rs4sim::rs4::rs232
