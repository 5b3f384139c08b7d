// Loading a mesh file for the picture subcommands: its ARG and where its nodes sit.
#pragma once

#include <string>

#include "common/build_options.hpp"
#include "graph/arg_graph.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/node_positions.hpp"

namespace argtool {

// Reads a mesh file (format detected from the content), its colours sampled from the texture
// image at `texture` when one is given (an OBJ's, as `argtool build --texture` reads it);
// errors name the path.
arg::Mesh read_mesh_file(const std::string& path, const std::string& texture = {});

struct RenderInput {
  std::string path;
  std::string name;  // file name without its folder, for captions
  arg::ArgGraph graph;
  arg::NodePositions positions;
};

// Builds the ARG exactly as `argtool build` and `argtool sim` do (so scores agree with them)
// and, when `with_positions`, the node positions from the same mesh and options.
RenderInput load_render_input(const std::string& path, const arg::BuildOptions& options,
                              bool with_positions = true);

}  // namespace argtool
