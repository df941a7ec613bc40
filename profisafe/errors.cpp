// Messages of the PROFIsafe layer's errors. See errors.h.
#include "profisafe/errors.h"

#include <string>

namespace rs4sim::profisafe {

std::string_view to_string(ProfisafeError e) noexcept {
  switch (e) {
    case ProfisafeError::kOk: return "no error";
    case ProfisafeError::kFParamsWrongSize: return "F-parameter block is not 10 bytes";
    case ProfisafeError::kFParamsReservedBits: return "F-parameter block has reserved bits set";
    case ProfisafeError::kFParamsIParCrcNeedsV2: return "F_iPar_CRC given for a non-V2 block";
    case ProfisafeError::kPduWrongSize: return "safety PDU has the wrong length";
    case ProfisafeError::kPduCrc2Mismatch: return "safety PDU CRC2 mismatch (CE_CRC)";
    case ProfisafeError::kPduConsecutiveNumber: return "safety PDU consecutive number not expected";
    case ProfisafeError::kPduUnsupportedCrcLength: return "CRC2 length not supported";
    case ProfisafeError::kPduDataTooLong: return "F-data size out of range 1..12";
    case ProfisafeError::kNotParameterised: return "no valid F-parameters";
  }
  return "unknown PROFIsafe error";
}

}  // namespace rs4sim::profisafe
