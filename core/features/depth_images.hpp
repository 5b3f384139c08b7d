// Orthographic depth images of a surface seen from the six faces of its bounding cube.
#pragma once

#include <array>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

// One N x N image per view: 1 at the cube face nearest the viewer, 0 at the far face and
// where nothing is seen. Views 2a and 2a + 1 look along axis a from its positive and its
// negative side; pixel (i, j) of view 2a + s samples axes (a + 1) % 3 and (a + 2) % 3.
struct DepthImages {
  int resolution = 0;
  std::array<std::vector<float>, 6> view;  // row-major, resolution^2 each
};

// Rasterises every triangle at pixel centres over the cube [-h, h]^3, where h is the largest
// absolute coordinate of the mesh (so the surface fills the images). Expects the aligned,
// centred frame of apply_pose.
DepthImages depth_images(const Mesh& mesh, int resolution);

}  // namespace arg
