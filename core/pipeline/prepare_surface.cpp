// Cleaning, pose normalisation and the choice between the mesh and its proxy.
#include "pipeline/prepare_surface.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "mesh/connected_components.hpp"
#include "mesh/fill_holes.hpp"
#include "mesh/surface_area.hpp"
#include "mesh/watertight_proxy.hpp"

namespace arg {

PreparedSurface prepare_surface(const Mesh& input, const BuildOptions& options,
                                const StopRequested& stop) {
  PreparedSurface out;
  Mesh mesh = clean_mesh(input, &out.clean, stop);
  // Whether the surface is in pieces, and how open it is, before any hole is filled: both
  // ratios below are the same before and after the pose.
  std::vector<int> component;
  out.components = std::size_t(vertex_components(mesh, component));
  // Components are numbered by decreasing area: the second one tells whether the surface is
  // in pieces or merely carries specks.
  double second = 0, total = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const double a = 0.5 * (mesh.V.row(mesh.F(f, 1)) - mesh.V.row(mesh.F(f, 0)))
                               .cross(mesh.V.row(mesh.F(f, 2)) - mesh.V.row(mesh.F(f, 0)))
                               .norm();
    total += a;
    if (component[std::size_t(mesh.F(f, 0))] == 1) second += a;
  }
  // The pose moves vertices and at most turns faces over (below): these edges serve the posed
  // mesh too (recomputed if holes are filled, which adds faces).
  out.posed_edges = mesh_edges(mesh.F);
  const MeshEdges& edges = out.posed_edges;
  double boundary = 0;
  for (int e = 0; e < edges.count(); ++e)
    if (edges.faces(e) == 1) boundary += (mesh.V.row(edges.v0[e]) - mesh.V.row(edges.v1[e])).norm();
  const bool broken =
      second >= 0.01 * total || out.clean.nonmanifold_edges * 1000 > std::size_t(edges.count());
  out.use_proxy =
      options.surface == SurfaceKind::Proxy || (options.surface == SurfaceKind::Auto && broken);
  // Holes alone do not call for the proxy: a manifold surface in one piece gets its holes
  // closed (fill_holes.hpp), unless it is wide open (a sheet: no closed shape to restore).
  const bool wide = boundary > 4.0 * std::sqrt(total);
  if (options.holes == HoleKind::Fill && !out.use_proxy && boundary > 0 && !wide &&
      out.clean.nonmanifold_edges == 0) {
    FillReport filled;
    mesh = fill_holes(mesh, &filled);
    out.filled_loops = filled.loops;
    if (filled.added_faces > 0) out.posed_edges = mesh_edges(mesh.F);
  }
  out.pose = surface_pose(mesh);
  if (!(out.pose.area > 0)) throw InputError("mesh has zero surface area");
  out.posed = apply_pose(mesh, out.pose);
  // A mirroring pose swaps each face's second and third corners (apply_pose): the edge a face
  // called its first (corners 0-1) is now its third (2-0), and the other way round.
  if (out.pose.rotation.determinant() < 0)
    for (std::int8_t& c : out.posed_edges.corner_of) c = std::int8_t(c == 1 ? 1 : 2 - c);
  out.boundary_length = boundary * out.pose.scale;
  out.area = surface_area(out.posed);
  if (out.use_proxy) {
    ProxyOptions proxy;
    proxy.resolution = options.proxy_resolution;
    out.proxy = watertight_proxy(out.posed, proxy, stop).mesh;
  }
  return out;
}

}  // namespace arg
