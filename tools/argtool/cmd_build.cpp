// argtool build: a mesh file to an ARG file.
#include <iostream>
#include <memory>

#include "command_registry.hpp"
#include "load_arg.hpp"

namespace {

struct BuildArgs {
  std::string mesh, texture, output;
  arg::BuildOptions options;
};

const bool registered = argtool::register_command(
    "build", "build the ARG of a mesh (OFF, OBJ, PLY, STL, GLB)", [](CLI::App& app) {
      auto a = std::make_shared<BuildArgs>();
      app.add_option("mesh", a->mesh, "mesh file")->required()->check(CLI::ExistingFile);
      app.add_option("--texture", a->texture, "texture image for OBJ")->check(CLI::ExistingFile);
      app.add_option("-o,--output", a->output, "ARG file to write (default: MESH.arg)");
      argtool::add_build_flags(app, a->options);
      return [a] {
        argtool::LoadedArg loaded = argtool::load_arg(a->mesh, a->options, a->texture);
        std::string out = a->output.empty() ? a->mesh + ".arg" : a->output;
        argtool::write_file_bytes(out, loaded.bytes);
        std::cout << out << ": " << loaded.graph.nodes.size() << " nodes, " << loaded.bytes.size()
                  << " bytes\n";
        return 0;
      };
    });

}  // namespace
