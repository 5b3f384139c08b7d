// The total area of a triangle mesh.
#pragma once

#include "mesh/mesh.hpp"

namespace arg {

// Sum of the triangles' areas, in the mesh's units squared (faces in order, so the same mesh
// gives the same bits).
double surface_area(const Mesh& mesh);

}  // namespace arg
