// Closing the holes of an open manifold mesh: each boundary loop gets a fan of triangles.
#pragma once

#include <cstddef>

#include "mesh/mesh.hpp"

namespace arg {

struct FillReport {
  std::size_t loops = 0;          // boundary loops closed
  std::size_t skipped_loops = 0;  // loops left open (they pass a vertex twice)
  std::size_t added_faces = 0;
};

// Closes every boundary loop of `mesh` that is a simple cycle: a loop of three edges gets one
// triangle, a longer one a new vertex at the mean of its vertices and a fan of triangles to it,
// turned like the faces along the loop (so a consistently oriented mesh stays so), coloured
// with the mean colour of those faces. A hole in a scan is a gap in the sampling, not in the
// object: mu (the geodesic integral), the spectrum and the views then see the surface the hole
// cut into rather than a rim that no other copy of the shape has. A loop that passes a vertex
// twice (two holes touching at a corner, or a non-manifold rim) is left as it is. Expects a
// mesh without non-manifold edges; deterministic.
Mesh fill_holes(const Mesh& mesh, FillReport* report = nullptr);

}  // namespace arg
