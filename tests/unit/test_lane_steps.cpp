// Shortest paths in lanes: the bucket queue's distances to the unit, whatever the sweep orders.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "common/errors.hpp"
#include "common/random.hpp"
#include "mesh/mesh_edges.hpp"
#include "mu/dijkstra.hpp"
#include "mu/lane_steps.hpp"
#include "mu/mu_function.hpp"
#include "mu/surface_graph.hpp"
#include "test_exact_meshes.hpp"

using namespace arg;

namespace {

// The refinement geodesic_integral gives a surface of m's area.
double integral_max_edge(const Mesh& m) {
  return geodesic_graph_max_edge(test::surface_area(m));
}

// Keys that order nodes by a coordinate, by a hash (an order unrelated to the surface) and by
// a constant (node order).
std::vector<std::uint32_t> by_coordinate(const Mesh& m, const SurfaceGraph& g, int axis) {
  std::vector<std::uint32_t> key(std::size_t(g.nodes()));
  for (int v = 0; v < g.nodes(); ++v) {
    const double x =
        v < g.mesh_vertices ? m.V(v, axis) : g.steiner[std::size_t(v - g.mesh_vertices)][axis];
    key[std::size_t(v)] = std::uint32_t((x + 10.0) * 1e5);
  }
  return key;
}

std::vector<std::uint32_t> scrambled(const SurfaceGraph& g) {
  std::vector<std::uint32_t> key(std::size_t(g.nodes()));
  for (int v = 0; v < g.nodes(); ++v) key[std::size_t(v)] = std::uint32_t(v) * 2654435761u;
  return key;
}

// Every lane against a bucket-queue run from its source, to the unit.
void expect_lanes_exact(const SurfaceGraph& g, const LaneGraph& lanes,
                        const std::vector<int>& sources, BucketScratch& scratch) {
  LaneRows rows;
  shortest_steps_lanes(lanes, sources.data(), int(sources.size()), rows);
  for (std::size_t l = 0; l < sources.size(); ++l) {
    shortest_steps(g, sources[l], scratch);
    for (int v = 0; v < g.nodes(); ++v)
      ASSERT_EQ(lane_distance(lanes, rows, v, int(l)), scratch.dist[std::size_t(v)])
          << "lane " << l << " source " << sources[l] << " node " << v;
  }
  for (int l = int(sources.size()); l < kLanes; ++l)
    EXPECT_EQ(lane_distance(lanes, rows, 0, l), kUnreached) << "an unused lane " << l;
  EXPECT_GT(rows.sweeps, 1);
}

}  // namespace

TEST(LaneSteps, EveryLaneIsTheBucketQueueRunWhateverTheOrders) {
  const Mesh tube = test::open_tube(25, 24, 0.5, 3), sphere = test::icosphere(4);
  const Mesh square = test::unit_square(30);
  for (const Mesh* m : {&tube, &sphere, &square}) {
    const SurfaceGraph g = surface_graph(*m, mesh_edges(m->F), integral_max_edge(*m));
    BucketScratch scratch;
    prepare_buckets(g, scratch);
    shortest_steps(g, 0, scratch);
    const std::vector<std::uint32_t> from_first = scratch.dist;
    const std::vector<std::vector<std::vector<std::uint32_t>>> schedules = {
        {from_first},
        {from_first, by_coordinate(*m, g, 0), by_coordinate(*m, g, 1), by_coordinate(*m, g, 2)},
        {scrambled(g)},
        {std::vector<std::uint32_t>(std::size_t(g.nodes()), 7u), scrambled(g)},
    };
    SeededRandom rng(11);
    for (const auto& keys : schedules) {
      const LaneGraph lanes = lane_graph(g, scratch, keys);
      ASSERT_TRUE(lanes.fits);
      std::vector<int> sixteen, three;
      for (int l = 0; l < kLanes; ++l) sixteen.push_back(int(rng.below(g.nodes())));
      for (int l = 0; l < 3; ++l) three.push_back(int(rng.below(g.nodes())));
      expect_lanes_exact(g, lanes, sixteen, scratch);
      expect_lanes_exact(g, lanes, three, scratch);
    }
  }
}

TEST(LaneSteps, ZeroLengthArcsAndUnreachedNodes) {
  // A path 0-1-2-3 whose middle arc quantises to no units, and a pair 4-5 apart from it.
  SurfaceGraph g;
  g.mesh_vertices = 6;
  const int a[] = {0, 1, 2, 4}, b[] = {1, 2, 3, 5};
  const float len[] = {1.0f, 1e-6f, 2.0f, 1.0f};
  g.offset.assign(7, 0);
  std::vector<std::vector<std::pair<int, float>>> adjacent(6);
  for (int e = 0; e < 4; ++e)
    adjacent[std::size_t(a[e])].push_back({b[e], len[e]}),
        adjacent[std::size_t(b[e])].push_back({a[e], len[e]});
  for (int v = 0; v < 6; ++v) {
    for (auto [w, l] : adjacent[std::size_t(v)]) g.target.push_back(w), g.length.push_back(l);
    g.offset[std::size_t(v) + 1] = int(g.target.size());
  }
  BucketScratch scratch;
  prepare_buckets(g, scratch);
  const LaneGraph lanes = lane_graph(g, scratch, {scrambled(g)});
  const std::vector<int> sources = {0, 3, 5};
  LaneRows rows;
  shortest_steps_lanes(lanes, sources.data(), 3, rows);
  EXPECT_EQ(lane_distance(lanes, rows, 2, 0), lane_distance(lanes, rows, 1, 0));
  EXPECT_EQ(lane_distance(lanes, rows, 4, 0), kUnreached);
  EXPECT_EQ(lane_distance(lanes, rows, 0, 2), kUnreached);
  EXPECT_EQ(lane_distance(lanes, rows, 4, 2), lane_distance(lanes, rows, 1, 0))
      << "arcs of the same length, the same units";
  for (int l = 0; l < 3; ++l) {
    shortest_steps(g, sources[std::size_t(l)], scratch);
    for (int v = 0; v < 6; ++v)
      EXPECT_EQ(lane_distance(lanes, rows, v, l), scratch.dist[std::size_t(v)]) << l << " " << v;
  }
}

TEST(LaneSteps, AStoppedRunThrowsAndTheNextIsWhole) {
  const Mesh sphere = test::icosphere(4);
  const SurfaceGraph g = surface_graph(sphere, mesh_edges(sphere.F), integral_max_edge(sphere));
  BucketScratch scratch;
  prepare_buckets(g, scratch);
  const LaneGraph lanes = lane_graph(g, scratch, {scrambled(g)});
  LaneRows rows;
  const std::vector<int> sources = {1, 2, 3};
  int polls = 0;
  const StopRequested third_poll = [&] { return ++polls == 3; };
  EXPECT_THROW(shortest_steps_lanes(lanes, sources.data(), 3, rows, third_poll), Interrupted);
  expect_lanes_exact(g, lanes, sources, scratch);
}

TEST(LaneSteps, TheIntegralIsTheSameForAnyThreadCount) {
  // Blocks of base points run in parallel; their sums are added in base-point order.
  const Mesh tube = test::open_tube(40, 36, 0.5, 3);
  const std::vector<double> one = geodesic_integral(tube, mesh_edges(tube.F), 96, 1);
  for (int threads : {2, 3, 8}) {
    const std::vector<double> more = geodesic_integral(tube, mesh_edges(tube.F), 96, threads);
    ASSERT_EQ(more.size(), one.size());
    for (std::size_t v = 0; v < one.size(); ++v)
      ASSERT_EQ(more[v], one[v]) << threads << " threads, vertex " << v;
  }
}
