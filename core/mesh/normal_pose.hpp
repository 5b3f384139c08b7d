// A second frame for view-based descriptors: principal axes of the surface normals (NPCA).
#pragma once

#include "mesh/mesh.hpp"
#include "mesh/normalize_pose.hpp"

namespace arg {

// On a mesh already centred and scaled (apply_pose of surface_pose), the rotation whose rows
// are the principal axes of the area-weighted normal directions n n^T, largest first, signed
// by the surface's third moment like surface_pose. Where the spread of the surface leaves its
// axes ambiguous (a cube, a cylinder as tall as wide), that of its normals often does not,
// so descriptors take the better of the two frames (Papadakis et al., PANORAMA).
Pose normal_pose(const Mesh& posed, const StopRequested& stop = {});

}  // namespace arg
