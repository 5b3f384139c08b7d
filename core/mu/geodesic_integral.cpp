// Hilaga's geodesic integral: K base points, Voronoi area weights, Dijkstra per base point.
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/parallel_for.hpp"
#include "mesh/surface_area.hpp"
#include "mu/dijkstra.hpp"
#include "mu/lane_steps.hpp"
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
    // Two passes, the first free of the second's dependence from one vertex to the next so
    // that it vectorises; the farthest is the first vertex of the largest gap, as before.
    const Eigen::RowVector3d p = V.row(next);
    for (int v = 0; v < n; ++v) gap[v] = std::min(gap[v], (V.row(v) - p).squaredNorm());
    const double largest = *std::max_element(gap.begin(), gap.end());
    const int far = int(std::find(gap.begin(), gap.end(), largest) - gap.begin());
    if (gap[far] == 0) break;
    next = far;
  }
  return chosen;
}

// Sweep orders for shortest_steps_lanes: the distance from the first base point (the rows'
// layout), then the projections on the four diagonals of the pose's axes. A path that runs
// against one order runs with another, so fewer sweeps reach the fixpoint than with the
// distance's order alone (docs/BENCHMARKS.md, "mu in lanes").
std::vector<std::vector<std::uint32_t>> sweep_keys(const Mesh& mesh, const SurfaceGraph& graph,
                                                   const std::vector<std::uint32_t>& distance) {
  const int n = graph.nodes();
  std::vector<std::vector<std::uint32_t>> keys{distance};
  const Eigen::Vector3d diagonals[4] = {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
  std::vector<double> along(static_cast<std::size_t>(n));
  for (const Eigen::Vector3d& d : diagonals) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (int v = 0; v < n; ++v) {
      const Eigen::Vector3d p = v < graph.mesh_vertices
                                    ? Eigen::Vector3d(mesh.V.row(v).transpose())
                                    : graph.steiner[std::size_t(v - graph.mesh_vertices)];
      along[std::size_t(v)] = p.dot(d);
      low = std::min(low, along[std::size_t(v)]);
      high = std::max(high, along[std::size_t(v)]);
    }
    // Whole steps of a 2^24th of the range: an order only needs to be about right.
    const double scale = high > low ? double(1 << 24) / (high - low) : 0.0;
    std::vector<std::uint32_t> key(static_cast<std::size_t>(n));
    for (int v = 0; v < n; ++v)
      key[std::size_t(v)] = std::uint32_t((along[std::size_t(v)] - low) * scale);
    keys.push_back(std::move(key));
  }
  return keys;
}

}  // namespace

double geodesic_graph_max_edge(double area) {
  return 2.0 * std::sqrt(4.0 * area / (std::sqrt(3.0) * 4000.0));
}

std::vector<double> geodesic_integral(const Mesh& mesh, const MeshEdges& edges, int base_points,
                                      int threads, const StopRequested& stop) {
  const int nv = int(mesh.V.rows());
  std::vector<double> varea = vertex_areas(mesh);
  check_interrupt(stop);
  double total_area = 0;
  for (double a : varea) total_area += a;
  SurfaceGraph graph = surface_graph(mesh, edges, geodesic_graph_max_edge(total_area), stop);
  check_interrupt(stop);

  std::vector<int> base = spread_base_points(mesh.V, base_points, stop);
  std::vector<float> dist;
  std::vector<int> nearest;
  shortest_paths(graph, base, dist, &nearest, stop);
  std::vector<double> weight(base.size(), 0.0);
  for (int v = 0; v < nv; ++v)
    if (nearest[v] >= 0) weight[nearest[v]] += varea[v];

  std::vector<double> mu(std::size_t(nv), 0.0);
  if (base.empty()) return mu;
  BucketScratch first;
  prepare_buckets(graph, first);
  const double unit = first.unit;
  // Each distance rounded to a float as shortest_paths_quantised gives it, and the runs added
  // in base-point order whatever computed them, so that mu's bytes (and the ARG's) do not
  // depend on the thread count or on the lanes.
  auto add = [&](std::size_t k, auto&& units) {
    const double s = weight[k];
    for (int v = 0; v < nv; ++v) {
      const std::uint32_t d = units(v);
      if (d != kUnreached) mu[std::size_t(v)] += s * double(float(d * unit));
    }
  };
  shortest_steps(graph, base[0], first, stop);
  add(0, [&](int v) { return first.dist[std::size_t(v)]; });
  const LaneGraph lanes = lane_graph(graph, first, sweep_keys(mesh, graph, first.dist), stop);
  check_interrupt(stop);
  const std::size_t blocks = (base.size() - 1 + kLanes - 1) / kLanes;
  const int workers = std::max(1, std::min<int>(threads, int(blocks)));
  if (lanes.fits) {
    // The other base points kLanes at a time, `workers` blocks in parallel. Block b: its first
    // base point and how many.
    auto block = [&](std::size_t b) {
      const std::size_t from = 1 + b * kLanes;
      return std::pair<std::size_t, int>(from,
                                         int(std::min<std::size_t>(kLanes, base.size() - from)));
    };
    // With workers, a round gives each about four blocks, so that a thread, started anew for
    // each round, outlives the cost of starting it.
    const std::size_t round = workers == 1 ? 1 : 4 * std::size_t(workers);
    std::vector<LaneRows> rows(round);
    for (std::size_t start = 0; start < blocks; start += round) {
      const std::size_t here = std::min<std::size_t>(round, blocks - start);
      parallel_for(here, workers, [&](std::size_t w) {
        const auto [from, count] = block(start + w);
        shortest_steps_lanes(lanes, base.data() + from, count, rows[w], stop);
      });
      check_interrupt(stop);
      for (std::size_t w = 0; w < here; ++w) {
        const auto [from, count] = block(start + w);
        for (int l = 0; l < count; ++l)
          add(from + std::size_t(l), [&](int v) { return lane_distance(lanes, rows[w], v, l); });
      }
    }
    return mu;
  }
  // A graph whose distances might not fit a lane: one bucket queue per base point.
  for (std::size_t k = 1; k < base.size(); ++k) {
    shortest_steps(graph, base[k], first, stop);
    add(k, [&](int v) { return first.dist[std::size_t(v)]; });
  }
  return mu;
}

}  // namespace arg
