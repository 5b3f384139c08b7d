// The --up option of the picture subcommands: which file axis points up, and the glTF default.
#pragma once

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <string>

namespace argtool {

// Adds --up AXIS (+x, -x, +y, -y, +z, -z), checked when parsed, to `app`, stored in `up`.
void add_up_option(CLI::App& app, std::string& up);

// The file's own up as a file axis: `up` when given, else +y for glTF (up by its specification),
// else zero (nothing says; arg::upright_frame then decides).
Eigen::Vector3d file_up(const std::string& path, const std::string& up);

}  // namespace argtool
