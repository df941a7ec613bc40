#pragma once
// Our master's F-hosts for the F-modules of GSD stations on one segment (the simulated bus of
// `rs4sim run --gsd FILE --link memory`, app/devices/gsd_segment.h): one profisafe::FHost per
// F-module, with the F-parameters the master's Set_Prm carries (the GSD's defaults), V1 or V2
// as they say. Sans-I/O: after each master cycle cycle() hands every F-host its module's part
// of the station's inputs (in data exchange), runs its watchdog and puts its next F-output PDU
// into the station's output image ([IEC 61784-3-3 F-Host behaviour]; docs/profisafe.md).
// Passivated by a fault, an F-host waits for ack_rei() once the communication is healthy again
// (ACK_REQ), as a safety program's operator acknowledgement; at start-up it reintegrates by
// itself (profisafe/f_host.h).

#include "dp/master/master.h"
#include "gsd/station/gsd_station.h"
#include "profisafe/f_host.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::gsd {

class FHostBank {
 public:
  // The F-hosts of every F-device of `stations` (which outlive the bank).
  explicit FHostBank(const std::vector<const GsdStation*>& stations);

  [[nodiscard]] bool empty() const noexcept { return hosts_.empty(); }
  // After a master cycle at `now`.
  void cycle(dp::master::Master& master, dp::TimePoint now);
  // The F-host of the F-module in slot index `module` of the station at `address` (nullptr:
  // none).
  [[nodiscard]] profisafe::FHost* find(std::uint8_t address, std::size_t module);
  [[nodiscard]] const profisafe::FHost* find(std::uint8_t address, std::size_t module) const;
  // The F-output data the F-host sends from its next new PDU on (size: the F-module's F-data;
  // zeros at first). false: no such F-host, or another size.
  bool set_output(std::uint8_t address, std::size_t module, std::span<const std::uint8_t> data);
  [[nodiscard]] std::span<const std::uint8_t> output(std::uint8_t address,
                                                     std::size_t module) const;

 private:
  struct Host {
    std::uint8_t address = 0;
    std::size_t module = 0;
    std::size_t input_offset = 0, output_offset = 0, pdu_size = 0;
    profisafe::FHost host;
    std::vector<std::uint8_t> output;  // as set
  };
  struct Image {
    std::uint8_t address = 0;
    std::vector<std::uint8_t> outputs;  // the station's whole output image
  };
  [[nodiscard]] const Host* host(std::uint8_t address, std::size_t module) const;

  std::vector<Host> hosts_;
  std::vector<Image> images_;
};

}  // namespace rs4sim::gsd
