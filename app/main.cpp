// rs4sim — the command-line entry point. See app/command.h for how sub-commands plug in.
#include "app/command.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>

namespace rs4sim::app {
std::vector<CommandInfo>& command_registry() {
  static std::vector<CommandInfo> registry;
  return registry;
}
}  // namespace rs4sim::app

int main(int argc, char** argv) {
  using namespace rs4sim::app;
  CLI::App cli{
      "rs4sim — virtual PROFIBUS-DP/PROFIsafe slave behaving like a Leuze ROTOSCAN "
      "RS4/PROFIsafe, with a class 1 master and tools"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", "rs4sim 0.1.0");

  auto& registry = command_registry();
  std::sort(registry.begin(), registry.end(),
            [](const CommandInfo& a, const CommandInfo& b) { return a.name < b.name; });
  std::vector<std::pair<CLI::App*, Action>> actions;
  for (auto& info : registry) {
    CLI::App* sub = cli.add_subcommand(info.name, info.description);
    actions.emplace_back(sub, info.setup(*sub));
  }

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help/--version exit 0; every parse error (unknown option, bad or missing value) is
    // a usage error: CLI11's message, exit 2 like every other usage error.
    return cli.exit(e) == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, action] : actions) {
      if (sub->parsed()) return action();
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
