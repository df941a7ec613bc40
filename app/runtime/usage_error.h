#pragma once
// The runtime's one error type for a bad combination of options that a parser could not
// catch: the CLI prints it and exits 2 (app/cli/command.h); the reason names the option.

#include <stdexcept>

namespace rs4sim::app {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace rs4sim::app
