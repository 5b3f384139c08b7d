// Loading an ARG from a file that holds either an ARG or a mesh (built on the fly).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "graph/arg_graph.hpp"
#include "pipeline/build_arg.hpp"

namespace argtool {

struct LoadedArg {
  arg::ArgGraph graph;
  std::string bytes;        // the binary form
  bool built = false;       // true when the file was a mesh
  arg::BuildReport report;  // filled when built
};

// Files starting with the ARG magic are read as ARGs; anything else is built as a mesh with
// `options` (and the texture file, when given) under the caps of `limits`.
LoadedArg load_arg(const std::string& path, const arg::BuildOptions& options = {},
                   const std::string& texture_path = "", const arg::Limits& limits = {});

// Adds --levels, --mu and --base-points (and --threads unless the subcommand has its own)
// to a subcommand, writing into `options`.
void add_build_flags(CLI::App& app, arg::BuildOptions& options, bool with_threads = true);

}  // namespace argtool
