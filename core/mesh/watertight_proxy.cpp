// The proxy: unsigned distance on a grid, the exterior flooded from the border and kept where
// it sees out, marching tetrahedra.
#include "mesh/watertight_proxy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "mesh/distance_field.hpp"
#include "mesh/marching_tetrahedra.hpp"

namespace arg {

namespace {

// Breadth first from the points in `queue`: `step(from, to)` is called for each 6-neighbour `to`
// of each point taken, and pushes `to` onto the queue when it takes it.
template <class Step>
void grow(const SampleGrid& g, std::vector<std::size_t>& queue, Step step,
          const StopRequested& stop) {
  const std::size_t nx = std::size_t(g.nx), ny = std::size_t(g.ny), nz = std::size_t(g.nz);
  for (std::size_t q = 0; q < queue.size(); ++q) {
    if ((q & 65535) == 0) check_interrupt(stop);
    const std::size_t k = queue[q], x = k % nx, y = (k / nx) % ny, z = k / (nx * ny);
    if (x > 0) step(k, k - 1);
    if (x + 1 < nx) step(k, k + 1);
    if (y > 0) step(k, k - nx);
    if (y + 1 < ny) step(k, k + nx);
    if (z > 0) step(k, k - nx * ny);
    if (z + 1 < nz) step(k, k + nx * ny);
  }
}

// Grid points reachable from the border in 6-neighbour steps through points where
// `passable(k, on_border)` holds.
template <class Passable>
std::vector<char> flood_from_border(const SampleGrid& g, Passable passable,
                                    const StopRequested& stop) {
  const std::size_t nx = std::size_t(g.nx), ny = std::size_t(g.ny), nz = std::size_t(g.nz);
  std::vector<char> reached(nx * ny * nz, 0);
  std::vector<std::size_t> queue;
  auto visit = [&](std::size_t k, bool border) {
    if (reached[k] || !passable(k, border)) return;
    reached[k] = 1;
    queue.push_back(k);
  };
  for (std::size_t z = 0; z < nz; ++z)
    for (std::size_t y = 0; y < ny; ++y)
      for (std::size_t x = 0; x < nx; ++x)
        if (x == 0 || y == 0 || z == 0 || x + 1 == nx || y + 1 == ny || z + 1 == nz)
          visit((z * ny + y) * nx + x, true);
  grow(
      g, queue, [&](std::size_t, std::size_t to) { visit(to, false); }, stop);
  return reached;
}

// How many of the 26 lattice directions (face, edge and corner neighbours' steps) lead from
// each grid point to the border through points farther than `offset` from the input. One sweep
// per direction: a point sees out along a step when it is free and the point one step on is
// past the border or sees out along the same step.
std::vector<std::uint8_t> open_directions(const DistanceField& field, double offset,
                                          const StopRequested& stop) {
  const SampleGrid& g = field.grid;
  const long nx = g.nx, ny = g.ny, nz = g.nz;
  const std::size_t n = field.distance.size();
  std::vector<std::uint8_t> count(n, 0);
  std::vector<char> sees(n, 0);
  for (int d = 0; d < 27; ++d) {
    const int dx = d % 3 - 1, dy = d / 3 % 3 - 1, dz = d / 9 - 1;
    if (dx == 0 && dy == 0 && dz == 0) continue;
    // The point one step on is visited first: walk each axis against the step. Every point is
    // written before it is read, so `sees` needs no clearing between directions.
    for (long zi = 0; zi < nz; ++zi) {
      check_interrupt(stop);
      const long z = dz > 0 ? nz - 1 - zi : zi;
      for (long yi = 0; yi < ny; ++yi) {
        const long y = dy > 0 ? ny - 1 - yi : yi;
        for (long xi = 0; xi < nx; ++xi) {
          const long x = dx > 0 ? nx - 1 - xi : xi;
          const std::size_t k = std::size_t((z * ny + y) * nx + x);
          if (!(double(field.distance[k]) > offset)) {
            sees[k] = 0;
            continue;
          }
          const long x2 = x + dx, y2 = y + dy, z2 = z + dz;
          const bool past = x2 < 0 || y2 < 0 || z2 < 0 || x2 >= nx || y2 >= ny || z2 >= nz;
          sees[k] = past || sees[std::size_t((z2 * ny + y2) * nx + x2)];
          count[k] = std::uint8_t(count[k] + (sees[k] ? 1 : 0));
        }
      }
    }
  }
  return count;
}

// Where a viewer from outside can go without coming within `offset` of the input; with
// `min_open`, only through what also sees out widely: the inside of a closed shape whose holes
// let the first flood in sees out only through the holes, and is filled as if they were closed.
std::vector<char> exterior(const DistanceField& field, double offset, int min_open,
                           const StopRequested& stop) {
  const std::vector<char> flooded = flood_from_border(
      field.grid, [&](std::size_t k, bool) { return double(field.distance[k]) > offset; }, stop);
  if (min_open == 0) return flooded;
  const std::vector<std::uint8_t> open = open_directions(field, offset, stop);
  return flood_from_border(
      field.grid,
      [&](std::size_t k, bool border) { return flooded[k] && (border || open[k] >= min_open); },
      stop);
}

// The nearest input triangle of the nearest grid point that knows one, for every grid point:
// the band's answers carried outwards in 6-neighbour steps. For proxy triangles outside the
// band, which close what saw out only through holes.
std::vector<std::int32_t> nearest_everywhere(const DistanceField& field,
                                             const StopRequested& stop) {
  std::vector<std::int32_t> nearest = field.nearest;
  std::vector<std::size_t> queue;
  for (std::size_t k = 0; k < nearest.size(); ++k)
    if (nearest[k] >= 0) queue.push_back(k);
  grow(
      field.grid, queue,
      [&](std::size_t from, std::size_t to) {
        if (nearest[to] >= 0) return;
        nearest[to] = nearest[from];
        queue.push_back(to);
      },
      stop);
  return nearest;
}

// Per proxy triangle, the input triangle nearest to the grid point nearest its centre that
// knows one: a corner of its cell where the proxy lies inside the band, else what the band's
// answers carried outwards give (where what saw out only through holes was closed).
std::vector<int> source_faces(const Mesh& proxy, const DistanceField& field,
                              const StopRequested& stop) {
  const SampleGrid& grid = field.grid;
  const int counts[3] = {grid.nx, grid.ny, grid.nz};
  const Eigen::Index m = proxy.F.rows();
  std::vector<int> source(std::size_t(m), -1);
  std::vector<std::int32_t> carried;
  for (int pass = 0; pass < 2; ++pass) {
    const std::vector<std::int32_t>& nearest = pass == 0 ? field.nearest : carried;
    for (Eigen::Index f = 0; f < m; ++f) {
      if (source[std::size_t(f)] >= 0) continue;
      const Eigen::RowVector3d c =
          (proxy.V.row(proxy.F(f, 0)) + proxy.V.row(proxy.F(f, 1)) + proxy.V.row(proxy.F(f, 2))) /
          3.0;
      int cell[3];
      for (int a = 0; a < 3; ++a)
        cell[a] =
            std::clamp(int(std::floor((c[a] - grid.origin[a]) / grid.step)), 0, counts[a] - 2);
      double best = HUGE_VAL;
      for (int corner = 0; corner < 8; ++corner) {
        const int x = cell[0] + (corner & 1), y = cell[1] + ((corner >> 1) & 1),
                  z = cell[2] + ((corner >> 2) & 1);
        const std::size_t at =
            (std::size_t(z) * std::size_t(grid.ny) + std::size_t(y)) * std::size_t(grid.nx) +
            std::size_t(x);
        const Eigen::RowVector3d p(grid.origin[0] + x * grid.step, grid.origin[1] + y * grid.step,
                                   grid.origin[2] + z * grid.step);
        const double gap = (p - c).squaredNorm();
        if (nearest[at] >= 0 && gap < best) best = gap, source[std::size_t(f)] = nearest[at];
      }
    }
    if (std::find(source.begin(), source.end(), -1) == source.end()) break;
    if (pass == 0) carried = nearest_everywhere(field, stop);
  }
  // Every point knows a triangle once the band's answers are carried (a proxy with faces has a
  // band); a -1 left would index the input's colours, so it cannot stay.
  if (std::find(source.begin(), source.end(), -1) != source.end())
    throw std::logic_error("proxy: a triangle has no source face");
  return source;
}

}  // namespace

Proxy watertight_proxy(const Mesh& mesh, const ProxyOptions& options, const StopRequested& stop) {
  if (mesh.V.rows() == 0 || mesh.F.rows() == 0) throw InputError("proxy: mesh has no faces");
  if (options.resolution < 8 || options.resolution > 512 || !(options.offset > 0) ||
      options.offset > 8)
    throw InputError("proxy: resolution must be in [8, 512] and offset in (0, 8] cells");
  if (options.min_open < 0 || options.min_open > 26)
    throw InputError("proxy: min_open " + std::to_string(options.min_open) +
                     " is outside [0, 26] (of the 26 lattice directions)");
  const Eigen::RowVector3d lo = mesh.V.colwise().minCoeff(), hi = mesh.V.colwise().maxCoeff();
  const double longest = (hi - lo).maxCoeff();
  if (!(longest > 0) || !std::isfinite(longest)) throw InputError("proxy: mesh has no extent");
  SampleGrid grid;
  grid.step = longest / options.resolution;
  // Room for the offset surface and two more cells, so the border is always outside.
  const int pad = int(std::ceil(options.offset)) + 2;
  int* counts[3] = {&grid.nx, &grid.ny, &grid.nz};
  for (int a = 0; a < 3; ++a) {
    const int cells = int(std::ceil((hi[a] - lo[a]) / grid.step - 1e-9));
    *counts[a] = cells + 2 * pad + 1;
    grid.origin[a] = 0.5 * (lo[a] + hi[a]) - 0.5 * (cells + 2 * pad) * grid.step;
  }
  const double offset = options.offset * grid.step;
  const DistanceField field = unsigned_distance_field(mesh, grid, offset + 1.5 * grid.step, stop);
  const std::vector<char> outside = exterior(field, offset, options.min_open, stop);

  // Outside: distance minus offset (positive). Elsewhere negative: the shell within the offset
  // (continuous with the outside across the surface), enclosed cavities and what saw out only
  // through holes (filled).
  const std::size_t layer = std::size_t(grid.nx) * std::size_t(grid.ny);
  Proxy proxy;
  proxy.mesh = marching_tetrahedra(grid, [&](int k, std::vector<double>& out) {
    check_interrupt(stop);
    out.resize(layer);
    for (std::size_t p = 0; p < layer; ++p) {
      const std::size_t at = std::size_t(k) * layer + p;
      const double d = double(field.distance[at]) - offset;
      out[p] = outside[at] ? d : std::min(d, 0.0) - (d > 0 ? grid.step : 0.0);
    }
  });
  if (proxy.mesh.F.rows() == 0) throw InputError("proxy: the surface encloses nothing");

  proxy.source_face = source_faces(proxy.mesh, field, stop);
  if (mesh.has_colour()) {
    const Eigen::Index m = proxy.mesh.F.rows();
    proxy.mesh.C.resize(m, 3);
    for (Eigen::Index f = 0; f < m; ++f)
      proxy.mesh.C.row(f) = mesh.C.row(proxy.source_face[std::size_t(f)]);
  }
  return proxy;
}

}  // namespace arg
