// The generator's solids through the shared marching tetrahedra: grid placement and sampling.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "gen/marching_tetrahedra.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mesh/marching_tetrahedra.hpp"

namespace arg::gen {
namespace {

// `resolution` cells along the longest side of the bounds, plus one cell of margin all round.
SampleGrid make_grid(const Box& bounds, int resolution) {
  const Vec3 extent = bounds.hi - bounds.lo;
  const double longest = std::max({extent.x, extent.y, extent.z});
  if (!(longest > 0) || !std::isfinite(longest))
    throw std::invalid_argument("marching_tetrahedra: empty or unbounded solid");
  SampleGrid g;
  g.step = longest / resolution;
  const auto cells = [&](double e) { return static_cast<int>(std::ceil(e / g.step - 1e-9)) + 2; };
  const int cx = cells(extent.x), cy = cells(extent.y), cz = cells(extent.z);
  const Vec3 centre = (bounds.lo + bounds.hi) * 0.5;
  g.origin[0] = centre.x - 0.5 * cx * g.step;
  g.origin[1] = centre.y - 0.5 * cy * g.step;
  g.origin[2] = centre.z - 0.5 * cz * g.step;
  g.nx = cx + 1;
  g.ny = cy + 1;
  g.nz = cz + 1;
  return g;
}

}  // namespace

double marching_grid_step(const Box& bounds, int resolution) {
  return make_grid(bounds, resolution).step;
}

Mesh marching_tetrahedra(const Solid& solid, int resolution) {
  if (resolution < 2) throw std::invalid_argument("marching_tetrahedra: resolution below 2");
  const SampleGrid g = make_grid(solid.bounds, resolution);
  return arg::marching_tetrahedra(g, [&](int k, std::vector<double>& out) {
    out.resize(static_cast<std::size_t>(g.nx) * g.ny);
    const double z = g.origin[2] + k * g.step;
    for (int j = 0; j < g.ny; ++j) {
      const double y = g.origin[1] + j * g.step;
      for (int i = 0; i < g.nx; ++i)
        out[static_cast<std::size_t>(j) * g.nx + i] =
            solid.field(Vec3{g.origin[0] + i * g.step, y, z});
    }
  });
}

}  // namespace arg::gen
