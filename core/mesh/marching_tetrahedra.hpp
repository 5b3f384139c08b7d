// The zero set of a field sampled on a regular grid as a closed, manifold, oriented mesh.
#pragma once

#include <functional>
#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

// Grid point (i, j, k), 0 <= i < nx and so on, lies at origin + step * (i, j, k).
struct SampleGrid {
  double origin[3] = {0, 0, 0};
  double step = 1;
  int nx = 0, ny = 0, nz = 0;
};

// Fills `layer` (nx * ny values, row-major in j then i) with the field at grid layer k;
// negative is inside. Called once per layer, in increasing k.
using LayerSampler = std::function<void(int k, std::vector<double>& layer)>;

// Polygonises the zero set with marching tetrahedra. The result is closed, manifold and
// oriented outwards, with no zero-area triangle, whatever the samples: exact zeros count as
// outside and the grid's outer layer is forced outside. Throws std::invalid_argument for a
// grid of fewer than two points along an axis or a NaN sample.
Mesh marching_tetrahedra(const SampleGrid& grid, const LayerSampler& sample);

}  // namespace arg
