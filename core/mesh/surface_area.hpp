// The total area of a triangle mesh, and each vertex's share of it.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

// Sum of the triangles' areas, in the mesh's units squared (faces in order, so the same mesh
// gives the same bits).
double surface_area(const Mesh& mesh);

// A third of the area of the triangles around each vertex (triangles in order, so the same mesh
// gives the same bits): the lumped area mu's base points and the surface measures weigh by.
std::vector<double> vertex_areas(const Mesh& mesh);

}  // namespace arg
