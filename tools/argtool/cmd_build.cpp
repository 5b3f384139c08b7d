// argtool build: a mesh file to an ARG file.
#include <iostream>
#include <memory>

#include "command_registry.hpp"
#include "common/errors.hpp"
#include "load_arg.hpp"

namespace {

struct BuildArgs {
  std::string mesh, texture, output;
  arg::BuildOptions options;
  std::size_t max_memory_mb = arg::Limits{}.max_build_bytes >> 20;
};

const bool registered = argtool::register_command(
    "build", "build the ARG of a mesh (OFF, OBJ, PLY, STL, GLB)", [](CLI::App& app) {
      auto a = std::make_shared<BuildArgs>();
      app.add_option("mesh", a->mesh, "mesh file")->required()->check(CLI::ExistingFile);
      app.add_option("--texture", a->texture, "texture image for OBJ")->check(CLI::ExistingFile);
      app.add_option("-o,--output", a->output, "ARG file to write (default: MESH.arg)");
      argtool::add_build_flags(app, a->options);
      app.add_option("--max-memory", a->max_memory_mb,
                     "megabytes the build may take, as arg.max_build_memory (0: no cap)")
          ->capture_default_str();
      return [a] {
        arg::Limits limits;
        limits.max_build_bytes = a->max_memory_mb << 20;
        argtool::LoadedArg loaded;
        try {
          loaded = argtool::load_arg(a->mesh, a->options, a->texture, limits);
        } catch (const arg::MemoryLimitError& e) {
          throw arg::MemoryLimitError(std::string(e.what()) + " (--max-memory)");
        }
        std::string out = a->output.empty() ? a->mesh + ".arg" : a->output;
        argtool::write_file_bytes(out, loaded.bytes);
        std::cout << out << ": " << loaded.graph.nodes.size() << " nodes, " << loaded.bytes.size()
                  << " bytes\n";
        return 0;
      };
    });

}  // namespace
