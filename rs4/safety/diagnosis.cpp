#include "rs4/safety/diagnosis.h"

#include <string>

namespace rs4sim::rs4::safety {
namespace {

using profisafe::FParameterFault;

struct Row {
  FParameterFault fault;
  FDiagnosis diagnosis;
};

// [RS4 manual §6.3, table 6.3-1], in the order the checks are made.
constexpr std::array<Row, 9> kTable{{
    {FParameterFault::kNone, FDiagnosis::kNone},
    {FParameterFault::kDestAddInvalid, FDiagnosis::kInternalDestAdd},
    {FParameterFault::kDestAddMismatch, FDiagnosis::kWrongDestAdd},
    {FParameterFault::kSourceAddInvalid, FDiagnosis::kWrongSourceAdd},
    {FParameterFault::kWdTimeInvalid, FDiagnosis::kWrongWdTime},
    {FParameterFault::kSilMismatch, FDiagnosis::kWrongSil},
    {FParameterFault::kCrcLengthMismatch, FDiagnosis::kWrongCrcLength},
    {FParameterFault::kVersionMismatch, FDiagnosis::kWrongBlockIdOrParVersion},
    {FParameterFault::kCrc1Mismatch, FDiagnosis::kWrongCrc1},
}};

}  // namespace

FDiagnosis diagnosis(FParameterFault f) noexcept {
  for (const Row& r : kTable) {
    if (r.fault == f) return r.diagnosis;
  }
  return FDiagnosis::kWrongBlockIdOrParVersion;  // not a block the RS4 knows
}

const char* to_string(FDiagnosis d) noexcept {
  for (const Row& r : kTable) {
    if (r.diagnosis == d) return profisafe::to_string(r.fault);
  }
  return "unknown F-parameter diagnosis";
}

std::array<std::uint8_t, 5> status_pdu(FDiagnosis d) noexcept {
  return {0x05, 0x81, 0x00, 0x00, static_cast<std::uint8_t>(d)};
}

std::string error_message(FDiagnosis d) {
  return std::to_string(static_cast<int>(d)) + " " + to_string(d);
}

}  // namespace rs4sim::rs4::safety
