#pragma once
// The METRON's line and reporting configuration as one command-line word list, for
// `rs4sim run --device metron --mode ...` (the app parses flags, this parses the word):
//   slave[,input=<type>][,scan-cycle=<ms>][,t-response=<ms>]   slave line mode (the default)
//   <reporting>[,<option>...]               standard line mode with that reporting mode:
//     continuous | periodical | on-request | status-change | input-related
//   options: binary | hex | decimal, separator, checksum, period=<ms>,
//            input=<no-function|enable-line|enable-all|start-stop-line|start-stop-all|
//                   line-standby|all-standby>, report=<m>[+<m>...] (first, last, count,
//            free, central, run), scan-cycle=<ms> (1..1000), t-response=<ms> (1..2000): the
//            scan cycle and Equation 3's t_response [METRON manual "Slave line mode"]
// e.g. "periodical,hex,separator,checksum,period=250" [docs/metron.md#running].

#include "metron/options.h"

#include <string>
#include <string_view>

namespace rs4sim::metron {

// Applies `spec` to `o`; returns "" or what is wrong with which word.
[[nodiscard]] std::string apply_mode_spec(std::string_view spec, Options& o);

}  // namespace rs4sim::metron
