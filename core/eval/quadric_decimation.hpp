// Decimation as modelling tools do it: quadric error metric edge collapses (OpenMesh's decimater).
#pragma once

#include "mesh/mesh.hpp"

namespace arg {

// Merges vertices at exactly the same position (a soup's unwelded corners are one point of the
// surface), then collapses edges cheapest quadric error first (Garland and Heckbert), never
// flipping a face, until at most `target_vertices` vertices are left or no collapse is allowed.
// Faces the halfedge structure cannot hold (a third face on an edge, a repeated corner) are kept
// where they were, with corners of their own (three more vertices each), detached from the
// decimated faces around them.
// Colours are not carried. Deterministic: the same mesh gives the same bytes.
Mesh quadric_decimation(const Mesh& mesh, std::size_t target_vertices);

}  // namespace arg
