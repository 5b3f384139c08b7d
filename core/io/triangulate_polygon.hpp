// Splitting one polygon of a mesh into triangles: a fan when convex, ear clipping otherwise.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace arg::io {

// Triangulates the polygon whose corners are `corners` (vertex indices into `xyz`, 3 doubles per
// vertex), appending corner positions (0..n-1, not vertex indices) as triples to `triangles`.
// Convex and nearly planar polygons become a fan; others are ear-clipped in their best-fit plane
// so that concave outlines (an L, a star) are covered without overlap. Ear clipping costs up to
// n^3 steps, charged to `work_budget` (shared by all polygons of a mesh, so that a file of many
// hostile polygons cannot make it slow); polygons with more than `max_ear_clipping` corners,
// degenerate ones, and the rest of a polygon when the budget runs out become fans.
void triangulate_polygon(const double* xyz, const int* corners, std::size_t n,
                         std::vector<std::array<std::size_t, 3>>& triangles,
                         std::size_t& work_budget, std::size_t max_ear_clipping = 256);

}  // namespace arg::io
