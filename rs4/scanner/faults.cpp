#include "rs4/scanner/faults.h"

namespace rs4sim::rs4::scanner {
namespace {

constexpr std::array<FaultInfo, kFaultCount> kInfo{{
    {0x0101, 0x0001, "ossd_cross_circuit"},
    {0x0201, 0x0002, "motor_speed"},
    {0x0102, 0x0001, "internal_hardware"},
    {0x0202, 0x0002, "dazzled"},
    {0x0302, 0x0003, "window_contaminated"},
    {0x0401, 0x0004, "field_pair_sequence"},
    {0x0402, 0x0004, "field_pair_invalid"},
    {0x0501, 0x0005, "unknown_command"},  // = rs4/adapter/rs4_commands.h kRs4ErrorUnknownCommand
}};

}  // namespace

const FaultInfo& fault_info(Fault f) noexcept {
  static constexpr FaultInfo kUnknown{0, 0, "unknown"};
  const auto i = static_cast<std::size_t>(f);
  return i < kInfo.size() ? kInfo[i] : kUnknown;
}

}  // namespace rs4sim::rs4::scanner
