// Conforming refinement of a mesh's large faces near given points (for cutting exact holes).
#pragma once

#include <functional>

#include <Eigen/Core>

#include "mesh/mesh.hpp"

namespace arg {

using NearFace = std::function<bool(const Eigen::RowVector3d&, const Eigen::RowVector3d&,
                                    const Eigen::RowVector3d&)>;

// Cuts into four, at its edge midpoints, every face with an edge longer than `max_edge` for
// which `near(a, b, c)` holds (a, b, c its corners), again on the new faces, until none is left
// or the mesh would pass `max_faces` faces. A neighbour that shares one or two of the split
// edges becomes two or three faces (two splits: the quadrilateral cut along its shorter
// diagonal), so the surface keeps its exact shape and no crack opens: an edge is split once for
// both of its faces, also where a soup's neighbouring triangles only share the positions of its
// end points. Colours follow their faces. Deterministic.
Mesh refine_faces(const Mesh& mesh, double max_edge, const NearFace& near, Eigen::Index max_faces);

}  // namespace arg
