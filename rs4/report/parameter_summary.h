#pragma once
// A short decoded summary of an RS4 parameter set: what the archive stores in its
// `summary` column (docs/storage.md) and what `rs4sim archive show` prints. Deterministic
// (one set, one byte string) and without the user passwords ([RS4 manual §7.2.4]: they
// belong to the device; the summary never shows them, not even whether they are set).

#include "rs4/scanner/parameter_set.h"

#include <string>

namespace rs4sim::rs4::report {

// "format" field of the summary JSON. 2: device_type and serial_number are the identity's
// text (rs4/scanner/identity_text.h), "0x0004" and "74565"; 1 gave numbers.
inline constexpr int kSummaryFormat = 2;

// One-line JSON, fields in a fixed order (docs/archive-cli.md "Summary"):
// {"format":2,"device_type":"0x0004","serial_number":"0","firmware":"1.0","response_time_ms":80,
//  "restart_mode":"...","start_pair":1,"permitted":[[1,2,3,4],...],"warning_output":[...],
//  "measurement":{"resolution":1,"start":0,"stop":528},
//  "pairs":[{"pair":1,"protective":{"min_mm":..,"max_mm":..,"active_segments":..},
//            "warning":{...}},...]}
std::string summary_json(const scanner::ParameterSet& set);

// The same facts as aligned text lines for a terminal.
std::string summary_text(const scanner::ParameterSet& set);

}  // namespace rs4sim::rs4::report
