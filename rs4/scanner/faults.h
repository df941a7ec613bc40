#pragma once
// Device faults of the scanner model. The RS4's own error numbers are not public (the
// manual only shows that 0x53/0x54 carry "error number, parameter, function" of the
// RS4, [RS4 manual §5.2.3.2, §5.2.3.3]): the numbers below are the project's (EXTENSION, documented
// in docs/rs4-scanner.md "Faults"). One value per fault
// ([docs/design.md#one-predicate-for-the-safe-state]).

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace rs4sim::rs4::scanner {

enum class Fault : std::uint8_t {
  kOssdCrossCircuit = 0,  // OSSD1/OSSD2 short or cross circuit (injectable)
  kMotorSpeed,            // rotation out of tolerance (injectable)
  kInternalHardware,      // internal self-test failed (injectable)
  kDazzled,               // receiver dazzled / no valid measurement (injectable)
  kWindowContaminated,    // contamination at or above the fault level
  kFieldPairSequence,     // field pair switched along a forbidden transition
  kFieldPairInvalid,      // field pair number not 1..4 reached the scanner
  kUnknownCommand,        // a telegram the RS4 does not know ([RS4 manual §5.2.2]: "RS4
                          // geht in Fehlerzustand"); parameter: the command byte
};
inline constexpr std::size_t kFaultCount = 8;

struct FaultInfo {
  std::uint16_t error_number;  // 0x53 "Fehler-Nummer"
  std::uint16_t function;      // 0x53 "Fehler-Funktion": the subsystem (docs table)
  std::string_view name;
};

// Number/function/name of a fault; {0, 0, "unknown"} for a value outside the enum.
const FaultInfo& fault_info(Fault f) noexcept;

// Warning numbers for 0x54 (EXTENSION).
inline constexpr std::uint16_t kWarningContaminationNumber = 0x0301;
inline constexpr std::uint16_t kWarningContaminationFunction = 0x0003;

// One value per fault: whether its cause is present now, whether it still needs an
// acknowledge (restart pulse once the cause is gone), and how often it occurred.
struct FaultState {
  bool present = false;
  bool latched = false;
  std::uint32_t occurrences = 0;
};
using FaultTable = std::array<FaultState, kFaultCount>;

}  // namespace rs4sim::rs4::scanner
