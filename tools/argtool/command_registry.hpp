// Subcommands of argtool register themselves here, one file per subcommand.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace argtool {

// Adds the subcommand's options to `app` and returns the function that runs it.
using CommandSetup = std::function<std::function<int()>(CLI::App& app)>;

struct Command {
  std::string name;
  std::string help;
  CommandSetup setup;
};

std::vector<Command>& commands();

// Called from a static initialiser in each subcommand's file.
bool register_command(std::string name, std::string help, CommandSetup setup);

// Reads a whole file into memory; throws std::runtime_error naming the path.
std::string read_file_bytes(const std::string& path);
void write_file_bytes(const std::string& path, const std::string& bytes);

}  // namespace argtool
