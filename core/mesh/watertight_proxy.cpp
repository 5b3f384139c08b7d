// The proxy: unsigned distance on a grid, the exterior flooded from the border, marching
// tetrahedra.
#include "mesh/watertight_proxy.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "mesh/distance_field.hpp"
#include "mesh/marching_tetrahedra.hpp"

namespace arg {

namespace {

// Grid points reachable from the border through points farther than `offset` from the input
// (6-neighbour steps), i.e. where a viewer from outside can go.
std::vector<char> flood_exterior(const DistanceField& field, double offset,
                                 const StopRequested& stop) {
  const SampleGrid& g = field.grid;
  const std::size_t nx = std::size_t(g.nx), ny = std::size_t(g.ny), nz = std::size_t(g.nz);
  std::vector<char> outside(field.distance.size(), 0);
  std::vector<std::size_t> queue;
  auto visit = [&](std::size_t k) {
    if (outside[k] || !(double(field.distance[k]) > offset)) return;
    outside[k] = 1;
    queue.push_back(k);
  };
  for (std::size_t z = 0; z < nz; ++z)
    for (std::size_t y = 0; y < ny; ++y)
      for (std::size_t x = 0; x < nx; ++x)
        if (x == 0 || y == 0 || z == 0 || x + 1 == nx || y + 1 == ny || z + 1 == nz)
          visit((z * ny + y) * nx + x);
  for (std::size_t q = 0; q < queue.size(); ++q) {
    if ((q & 65535) == 0) check_interrupt(stop);
    const std::size_t k = queue[q], x = k % nx, y = (k / nx) % ny, z = k / (nx * ny);
    if (x > 0) visit(k - 1);
    if (x + 1 < nx) visit(k + 1);
    if (y > 0) visit(k - nx);
    if (y + 1 < ny) visit(k + nx);
    if (z > 0) visit(k - nx * ny);
    if (z + 1 < nz) visit(k + nx * ny);
  }
  return outside;
}

}  // namespace

Proxy watertight_proxy(const Mesh& mesh, const ProxyOptions& options, const StopRequested& stop) {
  if (mesh.V.rows() == 0 || mesh.F.rows() == 0) throw InputError("proxy: mesh has no faces");
  if (options.resolution < 8 || options.resolution > 512 || !(options.offset > 0) ||
      options.offset > 8)
    throw InputError("proxy: resolution must be in [8, 512] and offset in (0, 8] cells");
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
  const std::vector<char> outside = flood_exterior(field, offset, stop);

  // Outside: distance minus offset (positive). Elsewhere negative: the shell within the offset
  // (continuous with the outside across the surface) and enclosed cavities (filled).
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

  // Each proxy triangle takes the input triangle nearest to the grid point nearest its centre
  // (the proxy lies inside the band, so some corner of its cell knows one).
  const Eigen::Index m = proxy.mesh.F.rows();
  proxy.source_face.assign(std::size_t(m), 0);
  for (Eigen::Index f = 0; f < m; ++f) {
    const Eigen::RowVector3d c =
        (proxy.mesh.V.row(proxy.mesh.F(f, 0)) + proxy.mesh.V.row(proxy.mesh.F(f, 1)) +
         proxy.mesh.V.row(proxy.mesh.F(f, 2))) /
        3.0;
    int cell[3];
    for (int a = 0; a < 3; ++a)
      cell[a] = std::clamp(int(std::floor((c[a] - grid.origin[a]) / grid.step)), 0, *counts[a] - 2);
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
      if (field.nearest[at] >= 0 && gap < best)
        best = gap, proxy.source_face[std::size_t(f)] = field.nearest[at];
    }
  }
  if (mesh.has_colour()) {
    proxy.mesh.C.resize(m, 3);
    for (Eigen::Index f = 0; f < m; ++f)
      proxy.mesh.C.row(f) = mesh.C.row(proxy.source_face[std::size_t(f)]);
  }
  return proxy;
}

}  // namespace arg
