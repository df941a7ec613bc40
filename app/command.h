#pragma once
// Sub-command registry of the rs4sim executable.
//
// Each sub-command lives in its own app/cmd_<name>.cpp and registers itself with a
// static `CommandRegistration`; main() builds the CLI11 tree from the registry. This keeps
// sub-commands independent of each other and of main.cpp.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace rs4sim::app {

// A sub-command adds its options to `cmd` and returns the action that runs it.
// The action returns the process exit code (0 = success). Errors the user can fix are
// reported on stderr with a specific message and a non-zero exit code; actions may also
// throw `UsageError` (exit 2) or any std::exception (exit 1) and main() prints it.
using Action = std::function<int()>;
using Setup = std::function<Action(CLI::App& cmd)>;

struct CommandInfo {
  std::string name;
  std::string description;
  Setup setup;
};

std::vector<CommandInfo>& command_registry();

struct CommandRegistration {
  CommandRegistration(std::string name, std::string description, Setup setup) {
    command_registry().push_back({std::move(name), std::move(description), std::move(setup)});
  }
};

// Thrown by an action for a bad combination of options the parser could not catch.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace rs4sim::app
