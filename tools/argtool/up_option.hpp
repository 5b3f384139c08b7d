// The --up option of the picture subcommands: which file axis points up, and the glTF default.
#pragma once

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <string>

#include "render/upright_frame.hpp"

namespace argtool {

// Adds --up AXIS (+x, -x, +y, -y, +z, -z), checked when parsed, to `app`, stored in `up`.
void add_up_option(CLI::App& app, std::string& up);

// The file's own up as a file axis: `up` when given, else +y for glTF (up by its specification),
// else zero (nothing says; arg::upright_frame then decides).
Eigen::Vector3d file_up(const std::string& path, const std::string& up);

// What the picture subcommands tell arg::upright_frame about the file at `path`: its own up
// (file_up) and its axes as columns in the surface's coordinates (`file_axes`: the identity
// for the surface as read, NodePositions::pose.rotation for the posed one), the file axes
// preferred where nothing says which is up.
arg::UprightHint upright_hint(const std::string& path, const std::string& up,
                              const Eigen::Matrix3d& file_axes = Eigen::Matrix3d::Identity());

}  // namespace argtool
