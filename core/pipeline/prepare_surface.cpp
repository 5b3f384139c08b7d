// Cleaning, pose normalisation and the choice between the mesh and its proxy.
#include "pipeline/prepare_surface.hpp"

#include "common/errors.hpp"
#include "mesh/connected_components.hpp"
#include "mesh/watertight_proxy.hpp"

namespace arg {

PreparedSurface prepare_surface(const Mesh& input, const BuildOptions& options,
                                const StopRequested& stop) {
  PreparedSurface out;
  Mesh mesh = clean_mesh(input, &out.clean, stop);
  out.pose = surface_pose(mesh);
  if (!(out.pose.area > 0)) throw InputError("mesh has zero surface area");
  out.posed = apply_pose(mesh, out.pose);
  std::vector<int> component;
  out.components = std::size_t(vertex_components(out.posed, component));
  // Components are numbered by decreasing area: the second one tells whether the surface is
  // in pieces or merely carries specks. Holes alone do not call for the proxy: mu crosses a
  // small hole nearly unchanged (the geodesic integral averages many paths).
  double second = 0, total = 0;
  for (Eigen::Index f = 0; f < out.posed.F.rows(); ++f) {
    const double a =
        0.5 * (out.posed.V.row(out.posed.F(f, 1)) - out.posed.V.row(out.posed.F(f, 0)))
                  .cross(out.posed.V.row(out.posed.F(f, 2)) - out.posed.V.row(out.posed.F(f, 0)))
                  .norm();
    total += a;
    if (component[std::size_t(out.posed.F(f, 0))] == 1) second += a;
  }
  out.area = total;
  out.posed_edges = mesh_edges(out.posed.F);
  const MeshEdges& edges_of = out.posed_edges;
  for (int e = 0; e < edges_of.count(); ++e)
    if (edges_of.faces(e) == 1)
      out.boundary_length +=
          (out.posed.V.row(edges_of.v0[e]) - out.posed.V.row(edges_of.v1[e])).norm();
  const std::size_t edges = std::size_t(edges_of.count());
  const bool broken = second >= 0.01 * total || out.clean.nonmanifold_edges * 1000 > edges;
  if (options.surface == SurfaceKind::Proxy || (options.surface == SurfaceKind::Auto && broken)) {
    ProxyOptions proxy;
    proxy.resolution = options.proxy_resolution;
    out.proxy = watertight_proxy(out.posed, proxy, stop).mesh;
  }
  return out;
}

}  // namespace arg
