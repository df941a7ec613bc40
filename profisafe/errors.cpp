// Error categories of the PROFIsafe layer. See errors.h and f_parameters.h.
#include "profisafe/errors.h"
#include "profisafe/f_parameters.h"

#include <string>

namespace rs4sim::profisafe {
namespace {

class ProfisafeCategory final : public std::error_category {
 public:
  [[nodiscard]] const char* name() const noexcept override { return "rs4sim.profisafe"; }
  [[nodiscard]] std::string message(int ev) const override {
    switch (static_cast<Errc>(ev)) {
      case Errc::kOk: return "no error";
      case Errc::kFParamsWrongSize: return "F-parameter block is not 10 bytes";
      case Errc::kFParamsReservedBits: return "F-parameter block has reserved bits set";
      case Errc::kFParamsIParCrcNeedsV2: return "F_iPar_CRC given for a non-V2 block";
      case Errc::kPduWrongSize: return "safety PDU has the wrong length";
      case Errc::kPduCrc2Mismatch: return "safety PDU CRC2 mismatch (CE_CRC)";
      case Errc::kPduConsecutiveNumber: return "safety PDU consecutive number not expected";
      case Errc::kPduUnsupportedCrcLength: return "CRC2 length not supported";
      case Errc::kPduDataTooLong: return "F-data size out of range 1..12";
      case Errc::kNotParameterised: return "no valid F-parameters";
    }
    return "unknown PROFIsafe error " + std::to_string(ev);
  }
};

class FDiagnosisCategory final : public std::error_category {
 public:
  [[nodiscard]] const char* name() const noexcept override { return "rs4sim.profisafe.fdiagnosis"; }
  [[nodiscard]] std::string message(int ev) const override {
    return std::to_string(ev) + " " + to_string(static_cast<FDiagnosis>(ev));
  }
};

}  // namespace

const std::error_category& profisafe_category() noexcept {
  static const ProfisafeCategory c;
  return c;
}

const std::error_category& fdiagnosis_category() noexcept {
  static const FDiagnosisCategory c;
  return c;
}

}  // namespace rs4sim::profisafe
