// Cleaning, pose normalisation and the choice between the mesh and its proxy.
#include "pipeline/prepare_surface.hpp"

#include <cmath>
#include <numeric>

#include "common/errors.hpp"
#include "mesh/bridge_pieces.hpp"
#include "mesh/collapse_short_edges.hpp"
#include "mesh/connected_components.hpp"
#include "mesh/face_subset.hpp"
#include "mesh/fill_holes.hpp"
#include "mesh/stitch_pieces.hpp"
#include "mesh/surface_area.hpp"
#include "mesh/watertight_proxy.hpp"

namespace arg {

namespace {

// Cleans a mesh made from a cleaned one; the counts of what was merged and dropped add up, and
// boundary_edges stays the input's (the open flag says the input was open, as when holes are
// filled); the rest (non-manifold edges, flips) describe the new mesh.
Mesh clean_again(const Mesh& mesh, CleanReport& report, const StopRequested& stop) {
  CleanReport again;
  Mesh out = clean_mesh(mesh, &again, stop);
  again.welded_vertices += report.welded_vertices;
  again.unused_vertices += report.unused_vertices;
  again.dropped_degenerate += report.dropped_degenerate;
  again.dropped_duplicate += report.dropped_duplicate;
  again.boundary_edges = report.boundary_edges;
  report = again;
  return out;
}

// Gaps narrower than this share of the bounding box's diagonal are tears, not space between
// parts: a cut that leaves its sides a fraction of a percent apart (perturb's split moves them
// 0.2% each), a scan's patches that stop short of each other.
constexpr double kTearGap = 0.01;
// A torn surface whose largest piece holds this share of the area is that piece: the rest are
// bits a hole cut off (a fingertip, the end of a tail), which mu would otherwise reach only
// through the proxy that rounds the shape's thin parts away.
constexpr double kMainPiece = 0.9;
// Rims of pieces that face each other with their centres within this share of the diagonal
// are joined by a tube (bridge_pieces.hpp): a hole wider than a limb leaves the limb's stump and
// the limb up to its diameter apart (perturb's large holes are balls of radius 6% of the
// diagonal: gaps up to 12%).
constexpr double kBridgeGap = 0.15;

// The faces of component 0 (clean_mesh then drops the vertices no kept face uses).
Mesh main_piece(const Mesh& mesh, const std::vector<int>& component) {
  std::vector<char> keep(std::size_t(mesh.F.rows()));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    keep[std::size_t(f)] = component[std::size_t(mesh.F(f, 0))] == 0;
  return face_subset(mesh, keep);
}

double boundary_length(const Mesh& mesh, const MeshEdges& edges) {
  double length = 0;
  for (int e = 0; e < edges.count(); ++e)
    if (edges.faces(e) == 1) length += (mesh.V.row(edges.v0[e]) - mesh.V.row(edges.v1[e])).norm();
  return length;
}

// A piece that is wide open (a boundary longer than 4 sqrt(area), PreparedSurface::wide_open)
// is a sheet, not a torn closed shape.
bool wide_open(double boundary, double area) {
  return boundary > 4.0 * std::sqrt(area);
}

// A manifold surface in open pieces (holes=fill): rims facing each other across a narrow gap are
// stitched, and when one piece then holds nearly all the area the others are set aside. Taken
// only when that leaves one closed-but-for-holes surface (specks under 1% aside, not wide open):
// a soup of open panels that stitching only partly joins, or joins into a sheet, stays as it
// was given and goes to the proxy. A model of closed parts (no rim) is never touched. Returns
// whether the mesh changed; `mesh_edges_given` are the mesh's as given.
bool join_torn_pieces(Mesh& mesh, const MeshEdges& mesh_edges_given, std::vector<int>& component,
                      PreparedSurface& out, const StopRequested& stop) {
  if (out.components < 2 || out.clean.nonmanifold_edges > 0 || out.clean.boundary_edges == 0)
    return false;
  const double diagonal = (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).norm();
  Mesh joined = mesh;
  CleanReport report = out.clean;
  std::vector<int> piece = component;
  std::size_t pieces = out.components, pairs = 0, set_aside = 0;
  const Mesh moved =
      stitch_pieces(mesh, mesh_edges_given, component, kTearGap * diagonal, &pairs, stop);
  if (pairs > 0) {
    joined = clean_again(moved, report, stop);
    // A stitch that pinched a few rims together (a rim vertex snapped where two sides met)
    // leaves a handful of fins: their faces go, and the small holes are filled below.
    if (report.nonmanifold_edges > 0) {
      const MeshEdges joined_edges = mesh_edges(joined.F, stop);
      if (report.nonmanifold_edges * 1000 <= std::size_t(joined_edges.count()))
        joined = clean_again(without_nonmanifold_faces(joined, joined_edges), report, stop);
    }
    if (report.nonmanifold_edges > 0) return false;
    pieces = std::size_t(vertex_components(joined, piece));
  }
  std::size_t tubes = 0;
  if (pieces > 1) {
    const Mesh bridged = bridge_pieces(joined, mesh_edges(joined.F, stop), piece,
                                       kBridgeGap * diagonal, &tubes, stop);
    // A tube whose cleaning leaves non-manifold edges (welded onto a rim it crosses) is not
    // kept; what stitching joined still is.
    CleanReport with_tubes = report;
    if (tubes > 0) {
      Mesh candidate = clean_again(bridged, with_tubes, stop);
      if (with_tubes.nonmanifold_edges == 0) {
        joined = std::move(candidate);
        report = with_tubes;
        pieces = std::size_t(vertex_components(joined, piece));
      } else {
        tubes = 0;
      }
    }
  }
  std::vector<double> area = component_areas(joined, piece, pieces);
  double total = std::accumulate(area.begin(), area.end(), 0.0);
  if (pieces > 1 && area[0] >= kMainPiece * total && area[1] >= 0.01 * total) {
    set_aside = pieces - 1;
    joined = clean_again(main_piece(joined, piece), report, stop);
    pieces = std::size_t(vertex_components(joined, piece));
    area = component_areas(joined, piece, pieces);
    total = std::accumulate(area.begin(), area.end(), 0.0);
  }
  if (pieces > 1 && area[1] >= 0.01 * total) return false;
  if (wide_open(boundary_length(joined, mesh_edges(joined.F, stop)), total)) return false;
  mesh = std::move(joined);
  component = std::move(piece);
  out.clean = report;
  out.components = pieces;
  out.stitched_pairs = pairs;
  out.bridged_pieces = tubes;
  out.set_aside_pieces = set_aside;
  return true;
}

}  // namespace

PreparedSurface prepare_surface(const Mesh& input, const BuildOptions& options,
                                const StopRequested& stop) {
  PreparedSurface out;
  // The cleaning's edge table serves the posed mesh too: the pose moves vertices and at most
  // turns faces over (below). Rebuilt when torn pieces are joined or holes filled.
  Mesh mesh = clean_mesh(input, &out.clean, stop, &out.posed_edges);
  // Whether the surface is in pieces, and how open it is, before any hole is filled: both
  // ratios below are the same before and after the pose.
  std::vector<int> component;
  out.components = std::size_t(vertex_components(mesh, component));
  // Between the steps below, each a pass or two over the faces (a few hundred milliseconds
  // together on millions of them).
  check_interrupt(stop);
  if (options.holes == HoleKind::Fill &&
      join_torn_pieces(mesh, out.posed_edges, component, out, stop))
    out.posed_edges = mesh_edges(mesh.F, stop);
  // Components are numbered by decreasing area: the second one tells whether the surface is
  // in pieces or merely carries specks.
  const std::vector<double> piece_area = component_areas(mesh, component, out.components);
  const double total = std::accumulate(piece_area.begin(), piece_area.end(), 0.0);
  const double second = piece_area.size() > 1 ? piece_area[1] : 0.0;
  check_interrupt(stop);
  const MeshEdges& edges = out.posed_edges;
  const double boundary = boundary_length(mesh, edges);
  check_interrupt(stop);
  const bool broken =
      second >= 0.01 * total || out.clean.nonmanifold_edges * 1000 > std::size_t(edges.count());
  out.use_proxy =
      options.surface == SurfaceKind::Proxy || (options.surface == SurfaceKind::Auto && broken);
  // Holes alone do not call for the proxy: a manifold surface in one piece gets its holes
  // closed (fill_holes.hpp), unless it is wide open (a sheet: no closed shape to restore).
  const bool wide = wide_open(boundary, total);
  if (options.holes == HoleKind::Fill && !out.use_proxy && boundary > 0 && !wide &&
      out.clean.nonmanifold_edges == 0) {
    FillReport filled;
    mesh = fill_holes(mesh, &filled);
    out.filled_loops = filled.loops;
    if (filled.added_faces > 0) out.posed_edges = mesh_edges(mesh.F, stop);
  }
  check_interrupt(stop);
  out.pose = surface_pose(mesh, stop);
  if (!(out.pose.area > 0)) throw InputError("mesh has zero surface area");
  check_interrupt(stop);
  out.posed = apply_pose(mesh, out.pose);
  check_interrupt(stop);
  // A mirroring pose swaps each face's second and third corners (apply_pose): the edge a face
  // called its first (corners 0-1) is now its third (2-0), and the other way round.
  if (out.pose.rotation.determinant() < 0)
    for (std::int8_t& c : out.posed_edges.corner_of) c = std::int8_t(c == 1 ? 1 : 2 - c);
  out.boundary_length = boundary * out.pose.scale;
  out.area = surface_area(out.posed);
  check_interrupt(stop);
  if (out.use_proxy) {
    ProxyOptions proxy;
    proxy.resolution = options.proxy_resolution;
    out.proxy = watertight_proxy(out.posed, proxy, stop).mesh;
  } else if (out.posed.V.rows() > kCoarseAbove) {
    CollapseOptions collapse;
    collapse.min_length = std::sqrt(4.0 * out.area / (std::sqrt(3.0) * kCoarseTriangles));
    out.coarse = collapse_short_edges(out.posed, collapse, stop, &out.coarse_vertex);
    out.coarse_edges = mesh_edges(out.coarse->F, stop);
  }
  return out;
}

}  // namespace arg
