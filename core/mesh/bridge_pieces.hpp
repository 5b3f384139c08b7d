// Bridging a surface that holes cut into pieces: rims of different pieces that face each other
// across a gap are joined by a tube.
#pragma once

#include <cstddef>
#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

// A hole wider than a limb cuts the limb off: what is left is the body with a rim where the
// limb was and the limb with a rim facing it, a gap between them that stitching (a tear's
// fraction of a percent) does not span. This joins such pairs of boundary loops: loops of
// different pieces (`component`: vertex_components' numbering) whose centres lie within
// `max_gap` of each other, of mean radii within a factor of four (a body's rim is wider than
// the limb's), each opening towards the other (its fan's normal, turned out of its piece, within
// about 45 degrees of the line to the other's centre: cosine 0.7). Only pieces whose whole rim is
// simple loops and whose fan-closed surface encloses some volume take part (which way a flat
// piece, or one with a pinched rim, is turned is unknown). Pairs are taken nearest first, a
// pair of unequal sizes counting as farther (gap times 1 + log of the radius ratio), each loop once
// and only while it joins pieces not yet joined; each becomes a tube: rings lerped between the two
// loops, about one a rim edge length apart (at most 16, and all tubes together at most as many
// vertices as the mesh), zipped to the loops by arc length after turning one
// loop to the start that fits the other best, its faces turned as the first loop's piece (a
// piece turned the other way is turned over when the result is cleaned). Returns the
// mesh with the tubes added (their faces take the mean colour of the two rims' faces);
// `bridges` (optional) receives the number of tubes. A mesh with more than 256 loops (a soup of
// open panels, not a cut surface) is returned as it is. Deterministic; polls `stop`.
Mesh bridge_pieces(const Mesh& mesh, const MeshEdges& edges, const std::vector<int>& component,
                   double max_gap, std::size_t* bridges = nullptr, const StopRequested& stop = {});

}  // namespace arg
