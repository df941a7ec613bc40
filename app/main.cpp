// rs4sim — the command-line entry point. See app/cli/command.h for how sub-commands plug in.
#include "app/cli/command.h"
#include "app/runtime/cli_words.h"
#include "app/runtime/run_session.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

namespace rs4sim::app {
std::vector<CommandInfo>& command_registry() {
  static std::vector<CommandInfo> registry;
  return registry;
}
}  // namespace rs4sim::app

int main(int argc, char** argv) {
  using namespace rs4sim::app;
  // Before anything else: a SIGINT/SIGTERM that arrives while a run is still starting waits
  // for its RunSession's handlers instead of killing the process half set up.
  block_stop_signals();
  CLI::App cli{
      "rs4sim — virtual PROFIBUS-DP/PROFIsafe slave behaving like a Leuze ROTOSCAN "
      "RS4/PROFIsafe, with a class 1 master and tools"};
  cli.require_subcommand(1);
  // Every parse error in the project's words (app/runtime/cli_words.h), with "did you mean".
  cli.failure_message(usage_failure);
  cli.set_version_flag("--version", "rs4sim 0.1.0");

  auto& registry = command_registry();
  std::sort(registry.begin(), registry.end(),
            [](const CommandInfo& a, const CommandInfo& b) { return a.name < b.name; });
  struct Parsed {
    CLI::App* sub;
    Action action;
    Signals signals;
  };
  std::vector<Parsed> actions;
  for (auto& info : registry) {
    CLI::App* sub = cli.add_subcommand(info.name, info.description);
    actions.push_back({sub, info.setup(*sub), info.signals});
  }

  // An unknown first word is named (CLI11 alone would only say that a subcommand is required).
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const auto& c : registry) names.push_back(c.name);
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      std::cerr << unknown_command(argv[1], names) << "\n";
      return 2;
    }
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help/--version exit 0; every parse error (unknown option, bad or missing value) is
    // a usage error: its message (usage_failure), exit 2 like every other usage error.
    return cli.exit(e) == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, action, signals] : actions) {
      if (!sub->parsed()) continue;
      if (signals == Signals::kDefault) unblock_stop_signals();
      return action();
    }
  } catch (const UsageError& e) {
    std::cerr << "rs4sim: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rs4sim: error: " << e.what() << "\n";
    return 1;
  }
  return 1;
}
