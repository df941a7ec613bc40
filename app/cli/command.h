#pragma once
// Sub-command registry of the rs4sim executable.
//
// Each sub-command lives in its own app/cmd_<name>.cpp and registers itself with a
// static `CommandRegistration`; main() builds the CLI11 tree from the registry. This keeps
// sub-commands independent of each other and of main.cpp.

#include "app/runtime/usage_error.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rs4sim::app {

// A sub-command adds its options to `cmd` and returns the action that runs it.
// The action returns the process exit code (0 = success). Errors the user can fix are
// reported on stderr with a specific message and a non-zero exit code; actions may also
// throw `UsageError` (exit 2) or any std::exception (exit 1) and main() prints it.
using Action = std::function<int()>;
using Setup = std::function<Action(CLI::App& cmd)>;

// Whether the command runs a RunSession (app/runtime/run_session.h): main() keeps SIGINT and
// SIGTERM blocked for those until the session has installed its handlers, and unblocks them
// for the others before their action runs.
enum class Signals { kDefault, kSession };

struct CommandInfo {
  std::string name;
  std::string description;
  Setup setup;
  Signals signals = Signals::kDefault;
};

std::vector<CommandInfo>& command_registry();

struct CommandRegistration {
  CommandRegistration(std::string name, std::string description, Setup setup,
                      Signals signals = Signals::kDefault) {
    command_registry().push_back(
        {std::move(name), std::move(description), std::move(setup), signals});
  }
};

// Actions throw UsageError (app/runtime/usage_error.h) for a bad combination of options the
// parser could not catch.

// One sub-command of a command with sub-commands (`rs4sim archive list`, `rs4sim param get`):
// its options go into its own Options object.
template <typename Options>
struct SubCommand {
  const char* name;
  const char* description;
  void (*options)(CLI::App& sub, Options& o);
  int (*run)(const Options& o);
};

// Registers every sub-command of `table` on `cmd` (exactly one required), each with the
// options `common` adds first (may be null) and its own; the action runs the one given.
template <typename Options, std::size_t N>
Action sub_commands(CLI::App& cmd, const SubCommand<Options> (&table)[N],
                    void (*common)(CLI::App& sub, Options& o) = nullptr) {
  cmd.require_subcommand(1);
  std::vector<std::pair<CLI::App*, std::shared_ptr<Options>>> subs;
  for (const auto& sc : table) {
    auto o = std::make_shared<Options>();
    CLI::App* sub = cmd.add_subcommand(sc.name, sc.description);
    if (common != nullptr) common(*sub, *o);
    sc.options(*sub, *o);
    subs.emplace_back(sub, o);
  }
  return [subs, &table]() -> int {
    for (std::size_t i = 0; i < subs.size(); ++i) {
      if (subs[i].first->parsed()) return table[i].run(*subs[i].second);
    }
    return 2;
  };
}

}  // namespace rs4sim::app
