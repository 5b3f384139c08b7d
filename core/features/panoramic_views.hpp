// Cylindrical projections of a surface about its three axes (the images of PANORAMA).
#pragma once

#include <array>
#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

// For axis a, a cylinder of radius `radius` and height 2 radius around it, centred at the
// origin, sampled at 2N angles by N heights. Image 2a ("extent") holds, per sample, the
// largest distance from the axis at which a surface point lies at that angle and height,
// divided by the radius (0 where none); image 2a + 1 ("orientation") holds |cos| of the angle
// between the surface normal there and the ray from the axis, raised to the 4th power so that
// only faces turned towards the cylinder count (Papadakis et al. 2010), averaged with the same
// measure of the normal the extent image's slope gives where that slope is not a jump (builder
// 1.4: noise that scatters the faces' normals leaves the slope alone). Rows are heights.
struct PanoramicViews {
  int height = 0, width = 0;                // N and 2N
  std::array<std::vector<float>, 6> image;  // row-major, height x width each
};

// Expects the centred, scaled frame of apply_pose (or any rotation of it).
PanoramicViews panoramic_views(const Mesh& mesh, int height, double radius,
                               const StopRequested& stop = {});

}  // namespace arg
