// Mesh files to ARGs plus node positions for render, render-match and sheet.
#include "render_input.hpp"

#include <filesystem>
#include <stdexcept>

#include "command_registry.hpp"
#include "common/errors.hpp"
#include "graph/serialize.hpp"
#include "io/read_mesh.hpp"
#include "pipeline/build_arg.hpp"

namespace argtool {

arg::Mesh read_mesh_file(const std::string& path, const std::string& texture) {
  const std::string bytes = read_file_bytes(path);
  if (bytes.compare(0, 4, "ARGR") == 0)
    throw std::runtime_error(path + ": an ARG file has no surface to draw; give the mesh");
  const std::string image = texture.empty() ? std::string() : read_file_bytes(texture);
  arg::ReadOptions read;
  read.texture = image;
  try {
    return arg::read_mesh(bytes, read);
  } catch (const arg::Error& e) {
    throw std::runtime_error((texture.empty() ? path : path + " with " + texture) + ": " +
                             e.what());
  }
}

RenderInput load_render_input(const std::string& path, const arg::BuildOptions& options,
                              bool with_positions) {
  RenderInput in;
  in.path = path;
  in.name = std::filesystem::path(path).filename().string();
  const arg::Mesh mesh = read_mesh_file(path);
  try {
    // Through the binary form, as load_arg does, so that nothing differs from `argtool sim`.
    in.graph = arg::deserialize_arg(arg::serialize_arg(arg::build_arg(mesh, options)));
    if (with_positions) in.positions = arg::node_positions(mesh, options);
  } catch (const arg::Error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return in;
}

}  // namespace argtool
