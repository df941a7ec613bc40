#include "rs4/rs232/port_options.h"

#include "rs4/protocol/parameter_transfer.h"

namespace rs4sim::rs4::rs232 {

std::optional<std::string> PortOptions::validate() const {
  if (!baud_code(baud)) {
    std::string text = "baud " + std::to_string(baud) + " is not one of";
    for (const auto b : kBaudRates) text += " " + std::to_string(b);
    return text;
  }
  // The largest answer: an upload chunk of the parameter transfer (1037 bytes).
  if (max_body < protocol::kMaxChunkSize + 64) {
    return "max_body " + std::to_string(max_body) + " is below " +
           std::to_string(protocol::kMaxChunkSize + 64) + " (a parameter chunk must fit)";
  }
  return std::nullopt;
}

}  // namespace rs4sim::rs4::rs232
