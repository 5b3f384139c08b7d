// argtool: builds, inspects, compares and evaluates Augmented Reeb Graphs from the command line.
#include <iostream>
#include <map>

#include "command_registry.hpp"
#include "common/errors.hpp"
#include "plugin_libraries.hpp"

int main(int argc, char** argv) {
  argtool::register_lazy_plugins();
  CLI::App app{"argtool: Augmented Reeb Graphs for 3D shape retrieval"};
  app.set_version_flag("--version", std::string("argtool ") + ARG_VERSION);
  app.require_subcommand(1);
  std::map<std::string, std::function<int()>> runners;
  for (auto& command : argtool::commands()) {
    CLI::App* sub = app.add_subcommand(command.name, command.help);
    runners[command.name] = command.setup(*sub);
  }
  CLI11_PARSE(app, argc, argv);
  try {
    for (auto* sub : app.get_subcommands()) return runners.at(sub->get_name())();
  } catch (const arg::LimitError& e) {
    std::cerr << "argtool: limit exceeded: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "argtool: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
