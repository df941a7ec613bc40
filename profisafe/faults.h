#pragma once
// Fault injection, a first-class control on both sides ([docs/design.md#faults-are-controls]): a
// PLC test must be able to provoke every fault the safety layer detects. Counters count down per
// PDU sent.

#include <cstdint>
#include <optional>

namespace rs4sim::profisafe {

// Faults in the PDUs a driver sends (FDevice responses or FHost requests).
struct PduFaults {
  unsigned corrupt_crc2 = 0;   // the next N PDUs go out with CRC2 low bit inverted
  unsigned repeat_number = 0;  // the next N PDUs repeat the previously sent PDU
  unsigned skip_number = 0;    // the next N new numbers skip one (n → n+2)
  bool mute = false;           // send nothing while set (the peer's watchdog expires)
  std::optional<std::uint16_t> crc1_override;  // compute CRC2 with this preset (wrong CRC1)

  [[nodiscard]] bool any() const noexcept {
    return corrupt_crc2 != 0 || repeat_number != 0 || skip_number != 0 || mute ||
           crc1_override.has_value();
  }
};

// Faults in the F-parameter block the host sends in Set_Prm (device answers 66/67/72).
struct ParameterFaults {
  std::optional<std::uint16_t> dest_add;    // wrong F_Dest_Add (→ 66)
  std::optional<std::uint16_t> source_add;  // wrong F_Source_Add (→ 67 if out of range)
  std::optional<std::uint16_t> par_crc;     // wrong F_Par_CRC (→ 72)
};

}  // namespace rs4sim::profisafe
