// argtool upright: the canonical up and front of mesh files, in each file's own coordinates.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "command_registry.hpp"
#include "mesh/normalize_pose.hpp"
#include "render/upright_frame.hpp"
#include "render_input.hpp"
#include "up_option.hpp"

namespace {

struct UprightArgs {
  std::vector<std::string> meshes;
  std::string up;  // the file axis that points up, for every file
};

// The file axis nearest to a direction: +X, -Y, ... (the labelled sets keep +Y or +Z up).
std::string nearest_axis(const Eigen::Vector3d& v) {
  Eigen::Index k = 0;
  v.cwiseAbs().maxCoeff(&k);
  return std::string(v[k] < 0 ? "-" : "+") + "XYZ"[k];
}

int run_upright(const UprightArgs& a) {
  // One line a file: the canonical up and front (the file's own up when --up or its format
  // says it, else the rule of arg::upright_frame with the file axes preferred), and the longest
  // principal axis (the up of the pictures before), each as a vector and as the nearest axis.
  std::printf("file\tup\tfront\tlongest\tup_vector\tfront_vector\n");
  for (const std::string& path : a.meshes) {
    const arg::Mesh mesh = argtool::read_mesh_file(path);
    const arg::UprightFrame frame = arg::upright_frame(mesh, argtool::upright_hint(path, a.up));
    const Eigen::Vector3d longest = arg::surface_pose(mesh).rotation.row(0).transpose();
    std::printf("%s\t%s\t%s\t%s\t%.4f,%.4f,%.4f\t%.4f,%.4f,%.4f\n", path.c_str(),
                nearest_axis(frame.up).c_str(), nearest_axis(frame.front).c_str(),
                nearest_axis(longest).c_str(), frame.up.x(), frame.up.y(), frame.up.z(),
                frame.front.x(), frame.front.y(), frame.front.z());
  }
  return 0;
}

const bool registered = argtool::register_command(
    "upright",
    "print the canonical up and front of meshes (the side each stands on is down), as TSV",
    [](CLI::App& app) {
      auto a = std::make_shared<UprightArgs>();
      app.add_option("meshes", a->meshes, "mesh files")->required()->check(CLI::ExistingFile);
      argtool::add_up_option(app, a->up);
      return [a] { return run_upright(*a); };
    });

}  // namespace
