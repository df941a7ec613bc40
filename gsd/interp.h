#pragma once
// GSD meaning ([PROFIBUS GSD spec]): syntax::File → Device. Unknown keywords are
// skipped (GSD files carry many keywords a master does not need); every keyword the
// interpreter uses is checked for kind and range, every reference is resolved, and
// every error names file:line and the offending text.

#include "gsd/error.h"
#include "gsd/model.h"
#include "gsd/syntax.h"

#include <string>
#include <string_view>

namespace rs4sim::gsd {

Result<Device> interpret(const syntax::File& file);

// parse_syntax + interpret: the usual entry point.
Result<Device> parse(std::string_view text, std::string file_name = "");

}  // namespace rs4sim::gsd
