// Hilaga's geodesic integral: K base points, Voronoi area weights, Dijkstra per base point.
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/parallel_for.hpp"
#include "mesh/surface_area.hpp"
#include "mu/dijkstra.hpp"
#include "mu/mu_function.hpp"
#include "mu/surface_graph.hpp"

namespace arg {

namespace {

// Farthest point sampling in space, from the vertex farthest from the centre of mass (the
// origin of a pose-normalised mesh), so the choice does not depend on vertex order.
std::vector<int> spread_base_points(const Vertices& V, int count, const StopRequested& stop) {
  const int n = int(V.rows());
  count = std::min(count, n);
  std::vector<int> chosen;
  std::vector<double> gap(std::size_t(n), std::numeric_limits<double>::infinity());
  int next = 0;
  for (int v = 1; v < n; ++v)
    if (V.row(v).squaredNorm() > V.row(next).squaredNorm()) next = v;
  while (int(chosen.size()) < count) {
    check_interrupt(stop);
    chosen.push_back(next);
    int far = 0;
    for (int v = 0; v < n; ++v) {
      gap[v] = std::min(gap[v], (V.row(v) - V.row(next)).squaredNorm());
      if (gap[v] > gap[far]) far = v;
    }
    if (gap[far] == 0) break;
    next = far;
  }
  return chosen;
}

// Typical edge length of a mesh of the same area made of about `faces` equilateral triangles.
double target_edge(double area, double faces) {
  return std::sqrt(4.0 * area / (std::sqrt(3.0) * faces));
}

}  // namespace

std::vector<double> geodesic_integral(const Mesh& mesh, const MeshEdges& edges, int base_points,
                                      int threads, const StopRequested& stop) {
  const int nv = int(mesh.V.rows());
  std::vector<double> varea = vertex_areas(mesh);
  check_interrupt(stop);
  double total_area = 0;
  for (double a : varea) total_area += a;
  SurfaceGraph graph = surface_graph(mesh, edges, 2.0 * target_edge(total_area, 4000.0), stop);
  check_interrupt(stop);

  std::vector<int> base = spread_base_points(mesh.V, base_points, stop);
  std::vector<float> dist;
  std::vector<int> nearest;
  shortest_paths(graph, base, dist, &nearest, stop);
  std::vector<double> weight(base.size(), 0.0);
  for (int v = 0; v < nv; ++v)
    if (nearest[v] >= 0) weight[nearest[v]] += varea[v];

  std::vector<double> mu(std::size_t(nv), 0.0);
  const int workers = std::max(1, std::min(threads, int(base.size())));
  // Blocks of base points run in parallel; their distances are added in base-point order, so
  // the sum (and so the ARG bytes) does not depend on the number of threads. With workers, a
  // block gives each four runs, so that a thread, started anew for each block, outlives the
  // cost of starting it (a run on a copy's graph takes a fraction of a millisecond).
  const int block = workers == 1 ? 1 : 4 * workers;
  std::vector<BucketScratch> scratch(static_cast<std::size_t>(block));
  for (auto& s : scratch) prepare_buckets(graph, s);
  for (std::size_t start = 0; start < base.size(); start += std::size_t(block)) {
    const int here = int(std::min<std::size_t>(std::size_t(block), base.size() - start));
    parallel_for(std::size_t(here), workers,
                 [&](std::size_t k) { shortest_steps(graph, base[start + k], scratch[k], stop); });
    check_interrupt(stop);
    // Each distance rounded to a float as shortest_paths_quantised gives it, so mu's bytes are
    // those of the float distances it was first written with.
    for (int k = 0; k < here; ++k) {
      const double s = weight[start + std::size_t(k)];
      const BucketScratch& run = scratch[std::size_t(k)];
      for (int v = 0; v < nv; ++v)
        if (run.dist[std::size_t(v)] != kUnreached)
          mu[v] += s * double(run.distance(std::size_t(v)));
    }
  }
  return mu;
}

}  // namespace arg
