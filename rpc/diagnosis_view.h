#pragma once
// A Slave_Diag answer decoded for rs4sim.v1.DiagnosisView (diagnosis.proto): the standard part
// by the standard's names, the extended diagnosis block by block [IEC 61158-6-3 Slave_Diag,
// DPV1 alarms, status PDUs], and the device's own texts for it (the RS4's tables, a GSD's
// Unit_Diag texts). A decoder of bytes from the bus: it never throws; what it cannot read is
// said in `error` and the blocks before it stay.

#include "rs4sim/v1/diagnosis.pb.h"

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace rs4sim::gsd {
struct GsdStationSpec;
}

namespace rs4sim::rpc {

// The device's texts for the extended diagnosis (the bytes after the 6 standard ones).
using DiagnosisTexts =
    std::function<std::vector<std::string>(std::span<const std::uint8_t> ext_diag)>;

// `du`: the Slave_Diag DU. `dpv1`: device-related blocks are alarm and status PDUs.
void fill_diagnosis(std::span<const std::uint8_t> du, bool dpv1, const DiagnosisTexts& texts,
                    v1::DiagnosisView& out);

// The RS4's words for its extended diagnosis: the status PDU's F-parameter diagnosis number
// [RS4 manual §6.3, table 6.3-1] and the diagnosis alarm's error numbers, each adapter error
// with the cause of [RS4 manual §5.3.2, table 5.3-3], "coming" or "going".
std::vector<std::string> rs4_diagnosis_texts(std::span<const std::uint8_t> ext_diag);

// A GSD station's words for its extended diagnosis (`spec` must outlive the result): the
// GSD's Unit_Diag_Bit, Unit_Diag_Not_Bit and Unit_Diag_Area texts of the device-related block
// with an F-device's diagnosis 64..71 by the GSD's X_Value or the standard's meaning
// (gsd::diagnosis_texts), then each slot the identifier-related block marks and each channel
// block, by the name of the module configured in that slot ("slot 1 "AI 2" channel 0 input:
// error 7 (upper limit exceeded)") [IEC 61158-6-3 Slave_Diag].
DiagnosisTexts gsd_diagnosis_texts(const gsd::GsdStationSpec& spec);

}  // namespace rs4sim::rpc
