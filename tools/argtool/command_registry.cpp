// The table of argtool subcommands and the small file helpers they share.
#include "command_registry.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace argtool {

std::vector<Command>& commands() {
  static std::vector<Command> table;
  return table;
}

bool register_command(std::string name, std::string help, CommandSetup setup) {
  commands().push_back({std::move(name), std::move(help), std::move(setup)});
  return true;
}

std::string read_file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

void write_file_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + path);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("short write to " + path);
}

}  // namespace argtool
