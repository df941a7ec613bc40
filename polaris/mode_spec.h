#pragma once
// The barrier's PC-tool settings [Polaris manual §7.4.2] as one command-line word list, for
// `rs4sim run --device polaris --mode ...` (the app parses flags, this parses the word; the
// same shape as metron/mode_spec.h and gridscan/mode_spec.h):
//   <data mode>[,<word>...]   485MB | FL1 | FL4 | FL10, then
//     slave | master, direct | reverse, object | hole (PN2), lsb | msb (485MB bit order),
//     nak | no-nak, start=<register> (decimal or 0x hex), scan-time=<ms>,
//     pn2-filter=<scans>, storage=none|object|hole, temporary | permanent (storage mode),
//     response-time=<us> (one scan; 0 = the model's), response-column=1|2
// e.g. "FL4,master,start=0,scan-time=20" (docs/polaris.md "Running").

#include "polaris/options.h"

#include <string>
#include <string_view>

namespace rs4sim::polaris {

// Applies `spec` to `o`; returns "" or what is wrong with which word (the ranges are
// Options::validate()'s, which the caller runs after).
[[nodiscard]] std::string apply_mode_spec(std::string_view spec, Options& o);

}  // namespace rs4sim::polaris
