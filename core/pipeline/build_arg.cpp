// The ARG pipeline: clean, normalise, mu, slice, Reeb levels, attributes, assemble.
#include "pipeline/build_arg.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/errors.hpp"
#include "common/heap_usage.hpp"
#include "features/curvature.hpp"
#include "features/laplace_spectrum.hpp"
#include "features/node_attributes.hpp"
#include "features/panorama_descriptor.hpp"
#include "features/shape_distributions.hpp"
#include "graph/serialize.hpp"
#include "mesh/mesh_edges.hpp"
#include "mesh/restrict_face_values.hpp"
#include "mesh/restrict_vertex_positions.hpp"
#include "mesh/surface_roughness.hpp"
#include "mesh/taubin_smoothing.hpp"
#include "mu/mu_function.hpp"
#include "pipeline/build_memory.hpp"
#include "pipeline/pool_fragments.hpp"
#include "pipeline/prepare_surface.hpp"
#include "reeb/reeb_levels.hpp"
#include "reeb/slice_intervals.hpp"

namespace arg {

namespace {

// Taubin iterations before curvature and the views on a rough surface: under Gaussian noise of
// 0.3% of the diagonal (perturb noise, strength 3) 10 left shrec07's queries .10 below their
// clean mAP, 80 leave them .03 below (docs/BENCHMARKS.md).
constexpr int kSmoothingRough = 80;
// On a fine surface that measures smooth, 10 iterations: the curvature of its tessellation is
// evened out as well as by 80 (every set's scores within .005, builder 1.8), for an eighth
// of the work, which on a 30,000-vertex scan was a fifth of its build.
constexpr int kSmoothingFine = 10;
// The mean normal offset (mesh/surface_roughness.hpp) above which a fine surface is rough: the
// clean models of shrec07 and shrec11 measure .03 to .093, the same with noise of 0.1% of the
// diagonal .088 to .196 and with 0.3% .159 to .309 (docs/BENCHMARKS.md).
constexpr double kRoughAbove = 0.125;

// The Taubin iterations a surface takes. A coarse mesh (mean edge over 2% of its bounding
// box's diagonal) takes none: its edges are its shape, and smoothing would round a
// 12-triangle box into a blob. A fine one (scans, fine meshes) takes kSmoothingRough when its
// normal offsets say noise of the size of an edge, else kSmoothingFine.
int smoothing_steps(const Mesh& mesh, const MeshEdges& edges, const StopRequested& stop) {
  double sum = 0;
  for (int e = 0; e < edges.count(); ++e)
    sum += (mesh.V.row(edges.v0[e]) - mesh.V.row(edges.v1[e])).norm();
  const double diagonal = (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).norm();
  if (edges.count() == 0 || sum / edges.count() >= 0.02 * diagonal) return 0;
  const std::vector<double> offsets = normal_offsets(mesh, edges, stop);
  double mean = 0;
  for (double r : offsets) mean += r;
  mean /= double(offsets.size());
  return mean > kRoughAbove ? kSmoothingRough : kSmoothingFine;
}

Mesh smoothed(const Mesh& mesh, const MeshEdges& edges, int iterations, const StopRequested& stop) {
  return taubin_smoothing(mesh, edges, iterations, 0.5, -0.53, stop);
}

// The curvature of the fine surface (smoothed where it is rough) carried to its collapsed
// copy's triangles: a coarser surface's dihedral angles and angle defects spread differently
// over its fewer triangles, and the curvature histograms built from them lost half of
// shrec07's first tier the copy cost.
TriangleCurvature fine_curvature(const PreparedSurface& prepared, const Mesh& smooth,
                                 const StopRequested& stop) {
  const TriangleCurvature on_fine = triangle_curvature(smooth, prepared.posed_edges, stop);
  TriangleCurvature out;
  out.mean =
      restrict_face_values(smooth, *prepared.coarse, prepared.coarse_vertex, on_fine.mean, stop);
  out.gaussian = restrict_face_values(smooth, *prepared.coarse, prepared.coarse_vertex,
                                      on_fine.gaussian, stop);
  return out;
}

class Stopwatch {
 public:
  double lap() {
    auto now = std::chrono::steady_clock::now();
    double ms = std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// Global node numbering by level, CSR children and adjacency.
void assemble(ArgGraph& g, std::vector<std::vector<ArgNode>>& per_level, const ReebGraph& reeb) {
  const int levels = int(per_level.size()) - 1;
  g.level_begin.assign(std::size_t(levels) + 2, 0);
  for (int r = 0; r <= levels; ++r)
    g.level_begin[std::size_t(r) + 1] =
        g.level_begin[std::size_t(r)] + std::uint32_t(per_level[std::size_t(r)].size());
  g.nodes.clear();
  for (int r = 0; r <= levels; ++r)
    for (ArgNode n : per_level[std::size_t(r)]) {
      if (r > 0) n.parent += std::int32_t(g.level_begin[std::size_t(r) - 1]);
      g.nodes.push_back(n);
    }
  // Each level's edges as global indices; link_graph derives the children from the parents.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (int r = 0; r <= levels; ++r)
    for (auto [a, b] : reeb.levels[std::size_t(r)].edges)
      edges.push_back({g.level_begin[std::size_t(r)] + std::uint32_t(a),
                       g.level_begin[std::size_t(r)] + std::uint32_t(b)});
  link_graph(g, edges);
}

}  // namespace

ArgGraph build_arg(const Mesh& input, const BuildOptions& options, const StopRequested& stop,
                   BuildReport* report) {
  BuildReport local;
  BuildReport& rep = report ? *report : local;
  if (options.levels < kMinLevels || options.levels > kMaxLevels)
    throw InputError("build options: levels must be in [" + std::to_string(kMinLevels) + ", " +
                     std::to_string(kMaxLevels) + "]");
  Stopwatch clock;

  const PreparedSurface prepared = prepare_surface(input, options, stop);
  const CleanReport& clean = prepared.clean;
  rep.welded_vertices = clean.welded_vertices;
  rep.dropped_degenerate = clean.dropped_degenerate;
  rep.dropped_duplicate = clean.dropped_duplicate;
  rep.flipped_faces = clean.flipped_faces;
  rep.boundary_edges = clean.boundary_edges;
  rep.nonmanifold_edges = clean.nonmanifold_edges;
  rep.components = prepared.components;
  rep.stitched_pairs = prepared.stitched_pairs;
  rep.bridged_pieces = prepared.bridged_pieces;
  rep.set_aside_pieces = prepared.set_aside_pieces;
  rep.filled_loops = prepared.filled_loops;
  rep.proxy = prepared.proxy.has_value();
  rep.ms.clean = clock.lap();
  const Mesh& mesh = prepared.surface();
  const MeshEdges proxy_edges = prepared.proxy ? mesh_edges(mesh.F, stop) : MeshEdges{};
  const MeshEdges& edges = prepared.proxy    ? proxy_edges
                           : prepared.coarse ? prepared.coarse_edges
                                             : prepared.posed_edges;
  rep.ms.normalise = clock.lap();

  const std::vector<double> mu = normalised_mu(mesh, edges, options, stop);
  rep.ms.mu = clock.lap();

  SlicedSurface sliced = slice_intervals(mesh, mu, 1 << options.levels, stop);
  ReebGraph reeb = reeb_levels(sliced, edges, options.levels, stop);
  rep.ms.reeb = clock.lap();

  // Curvature and the views' orientation images of a smoothed copy: dihedral angles and face
  // normals measure noise of the size of an edge as readily as shape, and a scan's noise would
  // otherwise fill the curvature histograms and speckle the views. A proxy is a level set
  // already smooth at its voxel size (and a soup's views see its parts as they are).
  // On a collapsed copy of a fine surface the fine surface is smoothed once, for its
  // curvature, and the views see the copy with each vertex at the mean of the smoothed fine
  // vertices collapsed into it (builder 1.7); a coarse surface's copy is seen as it is. A fine
  // surface takes 80 or 10 iterations by its roughness (builder 1.8). The fine smoothing counts as
  // smoothing in the build's timings (it was curvature's before 1.7).
  Stopwatch part;
  Mesh smooth, fine_smooth;
  const int steps =
      prepared.proxy ? 0 : smoothing_steps(prepared.posed, prepared.posed_edges, stop);
  const bool fine = steps > 0;
  rep.smoothing_steps = steps;
  if (prepared.coarse && fine) {
    fine_smooth = smoothed(prepared.posed, prepared.posed_edges, steps, stop);
    smooth = restrict_vertex_positions(mesh, prepared.coarse_vertex, fine_smooth.V, stop);
  } else if (fine) {
    smooth = smoothed(mesh, edges, steps, stop);
  } else if (!prepared.proxy) {
    smooth = mesh;
  }
  rep.ms.smoothing = part.lap();
  const TriangleCurvature curvature =
      prepared.coarse ? fine_curvature(prepared, fine ? fine_smooth : prepared.posed, stop)
                      : triangle_curvature(prepared.proxy ? mesh : smooth, edges, stop);
  fine_smooth = Mesh{};  // the fine surface's size, not needed past its curvature
  rep.ms.curvature = part.lap();
  double volume = 0;
  std::vector<std::vector<ArgNode>> per_level =
      node_attributes(mesh, sliced, reeb, curvature, &volume, stop);
  check_interrupt(stop);
  rep.ms.nodes = part.lap();

  ArgGraph g;
  g.options = options;
  g.options.threads = 1;
  g.builder_version = current_builder_version();
  assemble(g, per_level, reeb);
  const Pose& pose = prepared.pose;
  ArgSummary& s = g.summary;
  s.triangles = std::uint32_t(prepared.posed.F.rows());  // of the cleaned input, not the proxy
  s.vertices = std::uint32_t(prepared.posed.V.rows());
  s.components = std::uint16_t(std::min<std::size_t>(rep.components, 65535));
  s.genus = std::uint16_t(std::clamp(reeb.loops, 0, 65535));
  s.has_colour = mesh.has_colour() ? 1 : 0;
  s.flags =
      std::uint16_t((clean.boundary_edges > 0 ? kFlagOpen : 0) | (rep.proxy ? kFlagProxy : 0) |
                    (prepared.wide_open() ? kFlagWideOpen : 0));
  s.area = float(pose.area);
  s.scale = float(pose.scale);
  s.volume = float(volume / (pose.scale * pose.scale * pose.scale));
  GraphCounts counts;
  for (int r = 0; r <= options.levels; ++r)
    counts.nodes_per_level[std::size_t(r)] = int(per_level[std::size_t(r)].size());
  counts.loops = reeb.loops;
  counts.components = int(rep.components);
  g.global = global_descriptor(mesh, pose, counts, volume, stop);
  check_interrupt(stop);
  rep.ms.global = part.lap();
  // The spectrum only counts between models whose surface is the shape's own (similarity.cpp).
  if (!(s.flags & (kFlagProxy | kFlagWideOpen)))
    g.spectrum = laplace_spectrum(mesh, kSpectrumSize, stop);
  check_interrupt(stop);
  rep.ms.spectrum = part.lap();
  // The views see the model as it was given, not its proxy: a soup's parts as they are.
  g.panorama = panorama_descriptor(prepared.proxy ? prepared.posed : smooth, stop);
  check_interrupt(stop);
  pool_fragments(g, max_nodes_per_level(options.levels));
  rep.ms.views = part.lap();
  rep.ms.features = clock.lap();
  // What a reader of the stored value will see: SIM is the same for a graph just built and
  // the same graph stored and read back.
  return stored_form(g);
}

std::string build_arg_bytes(std::string_view mesh_bytes, std::string_view texture,
                            const BuildOptions& options, const Limits& limits,
                            const StopRequested& stop, BuildReport* report) {
  BuildReport local;
  BuildReport& rep = report ? *report : local;
  if (mesh_bytes.size() > limits.max_input_bytes)
    throw LimitError("mesh of " + std::to_string(mesh_bytes.size()) + " bytes exceeds the cap of " +
                     std::to_string(limits.max_input_bytes) + " bytes");
  // Every poll from here on also holds the heap to the cap, the reading included: the estimate
  // below is a bound fitted to measured builds, this is the backstop for the mesh it misses.
  const StopRequested bounded = bounded_by_heap(stop, limits.max_build_bytes);
  Stopwatch clock;
  ReadOptions read;
  read.limits = limits;
  read.texture = texture;
  read.stop = bounded;
  // Refused from what the file declares, before the reader allocates for it; checked again
  // below on the counts read (a PLY's polygons become more triangles than its faces).
  read.declared_counts = [&](std::size_t vertices, std::size_t faces) {
    check_build_memory(vertices, faces, options, limits.max_build_bytes);
  };
  Mesh mesh = read_mesh(mesh_bytes, read, &rep.read);
  double read_ms = clock.lap();
  // Refused before the build's large allocations, as soon as the counts are known.
  check_build_memory(std::size_t(mesh.V.rows()), std::size_t(mesh.F.rows()), options,
                     limits.max_build_bytes);
  ArgGraph g = build_arg(mesh, options, bounded, &rep);
  rep.ms.read = read_ms;
  clock.lap();
  std::string bytes = serialize_arg(g);
  rep.ms.serialise = clock.lap();
  return bytes;
}

}  // namespace arg
