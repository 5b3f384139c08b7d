// Turning an implicit solid into a closed, manifold, outward-oriented triangle mesh.
#pragma once

#include "gen/implicit_solid.hpp"
#include "mesh/mesh.hpp"

namespace arg::gen {

// Samples solid.field on a grid with `resolution` cells along the longest side of
// solid.bounds (plus one cell of margin all round) and polygonises the zero set with marching
// tetrahedra (mesh/marching_tetrahedra.hpp). The result is closed, manifold and oriented
// outwards, with no zero-area triangle, whatever the field; thin parts below about a cell may
// vanish or pinch, which changes the topology, so the model classes keep their parts a few
// cells thick.
Mesh marching_tetrahedra(const Solid& solid, int resolution);

// The grid spacing marching_tetrahedra uses for these bounds and resolution.
double marching_grid_step(const Box& bounds, int resolution);

}  // namespace arg::gen
