#pragma once
// The curtain's configuration as one command-line word list, for
// `rs4sim run --device gridscan --mode ...` (the app parses flags, this parses the word; the
// same shape as metron/mode_spec.h and polaris/mode_spec.h):
//   blanking | static            the delivery mode [GridScan manual §10.4]
//   [,cycle=<ms>]                t_CYCLE, inside the manual's band for the element count
// e.g. "static,cycle=40". Options::elements must be set before (the band depends on it).

#include "gridscan/options.h"

#include <string>
#include <string_view>

namespace rs4sim::gridscan {

// Applies `spec` to `o`; returns "" or what is wrong with which word.
[[nodiscard]] std::string apply_mode_spec(std::string_view spec, Options& o);

}  // namespace rs4sim::gridscan
