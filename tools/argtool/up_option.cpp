// The --up option: parsed by arg::parse_up_axis, so the CLI and the library accept the same words.
#include "up_option.hpp"

#include <stdexcept>

#include "command_registry.hpp"
#include "io/read_mesh.hpp"
#include "render/upright_frame.hpp"

namespace argtool {

void add_up_option(CLI::App& app, std::string& up) {
  app.add_option("--up", up,
                 "the file axis that points up (+x, -x, +y, -y, +z, -z), when the file's "
                 "catalogue says it; default: +y for glTF, else the side the model stands on")
      ->check(CLI::Validator(
          [](std::string& s) {
            try {
              arg::parse_up_axis(s);
              return std::string();
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
          },
          "AXIS", "up axis"));
}

Eigen::Vector3d file_up(const std::string& path, const std::string& up) {
  if (!up.empty()) return arg::parse_up_axis(up);
  if (arg::detect_mesh_format(read_file_bytes(path)) == arg::MeshFormat::Glb)
    return Eigen::Vector3d::UnitY();
  return Eigen::Vector3d::Zero();
}

arg::UprightHint upright_hint(const std::string& path, const std::string& up,
                              const Eigen::Matrix3d& file_axes) {
  arg::UprightHint hint;
  hint.file_axes = file_axes;
  hint.up = file_up(path, up);
  hint.prefer_file_axes = true;
  return hint;
}

}  // namespace argtool
