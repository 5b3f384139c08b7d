// Shortest paths on the Steiner-refined surface graph and the geodesic integral, against exact
// geodesics of a plane, a tube and a sphere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "common/errors.hpp"
#include "mesh/mesh_edges.hpp"
#include "mu/dijkstra.hpp"
#include "mu/mu_function.hpp"
#include "mu/surface_graph.hpp"
#include "test_exact_meshes.hpp"

using namespace arg;

namespace {

// The refinement geodesic_integral gives a surface of m's area.
double integral_max_edge(const Mesh& m) {
  return geodesic_graph_max_edge(test::surface_area(m));
}

// max_edge = edge length x this gives an edge surface_graph's most Steiner points (8).
constexpr double kFinest = 1.0 / 8.5;

// Relative errors (graph - exact) / exact of the distances from `source` to every mesh vertex
// at least `near` away, as the graph's shortest paths give them.
struct Errors {
  double over = 0, under = 0, mean = 0;
};

Errors errors(const Mesh& m, double max_edge, int source, const std::function<double(int)>& exact,
              double near) {
  const SurfaceGraph g = surface_graph(m, mesh_edges(m.F), max_edge);
  std::vector<float> d;
  shortest_paths(g, {source}, d);
  Errors e;
  e.over = -INFINITY, e.under = INFINITY;
  int count = 0;
  for (int v = 0; v < int(m.V.rows()); ++v) {
    const double x = exact(v);
    if (x < near) continue;
    const double rel = (double(d[std::size_t(v)]) - x) / x;
    e.over = std::max(e.over, rel), e.under = std::min(e.under, rel), e.mean += rel, ++count;
  }
  e.mean /= count;
  return e;
}

// Smallest distance from the centre to the planes of the faces: an inscribed polyhedron's
// paths, pushed out radially onto the unit sphere, grow by at most 1 / this.
double inradius(const Mesh& m) {
  double r = INFINITY;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    r = std::min(r, std::fabs((b - a).cross(c - a).normalized().dot(a)));
  }
  return r;
}

}  // namespace

TEST(GeodesicIntegral, OnAPlaneSteinerPointsCutTheDetourAcrossTheDiagonals) {
  const Mesh m = test::unit_square(10);  // edges 0.1 and 0.141
  const int centre = 5 * 11 + 5;
  auto euclid = [&](int v) { return (m.V.row(v) - m.V.row(centre)).norm(); };
  // Edges alone: towards (1, -1) a path zigzags along the two legs, sqrt(2) times too long.
  const Errors edges = errors(m, 0, centre, euclid, 0.2);
  EXPECT_NEAR(edges.over, std::sqrt(2.0) - 1, 1e-6);
  // The integral's refinement puts 2 points on each edge here: worst 5.69%, mean 2.26%.
  const Errors used = errors(m, integral_max_edge(m), centre, euclid, 0.2);
  EXPECT_LT(used.over, 0.065);
  EXPECT_LT(used.mean, 0.026);
  // 8 points per edge: worst 0.663%.
  const Errors finest = errors(m, 0.1 * kFinest, centre, euclid, 0.2);
  EXPECT_LT(finest.over, 0.0075);
  // A path in the plane is never shorter than the straight line (up to float sums).
  for (const Errors& e : {edges, used, finest}) EXPECT_GE(e.under, -1e-5);
}

TEST(GeodesicIntegral, OnATubeDistancesAreThoseOfTheUnrolledStrip) {
  const int rows = 25, cols = 24;
  const double radius = 0.5, length = 3, chord = 2 * radius * std::sin(M_PI / cols);
  const Mesh m = test::open_tube(rows, cols, radius, length);
  const int source = 12 * cols;  // halfway up
  // Unrolled, the prism is a strip of width cols x chord, glued along its long sides: the
  // shorter way round is the exact geodesic.
  auto unrolled = [&](int v) {
    int around = std::abs(v % cols - source % cols);
    around = std::min(around, cols - around);
    return std::hypot(length * (v / cols - source / cols) / (rows - 1), around * chord);
  };
  // The integral's refinement puts one point on each diagonal only: worst 8.73%, mean 5.17%.
  const Errors used = errors(m, integral_max_edge(m), source, unrolled, 0.3);
  EXPECT_LT(used.over, 0.10);
  EXPECT_LT(used.mean, 0.06);
  // 8 points per edge: worst 0.705%.
  const Errors finest = errors(m, 0.125 * kFinest, source, unrolled, 0.3);
  EXPECT_LT(finest.over, 0.0082);
  // The strip is flat: no path is shorter than the straight line across it.
  for (const Errors& e : {used, finest}) EXPECT_GE(e.under, -1e-5);
}

TEST(GeodesicIntegral, OnASphereDistancesFollowGreatCircles) {
  const Mesh m = test::icosphere(2);  // 320 faces, edges 0.276 to 0.325 long
  auto arc = [&](int v) { return std::acos(std::clamp(m.V.row(v).dot(m.V.row(0)), -1.0, 1.0)); };
  // The integral's refinement puts one point on each edge: from +2.78% to -0.82%.
  const Errors used = errors(m, integral_max_edge(m), 0, arc, 0.3);
  EXPECT_LT(used.over, 0.033);
  // 7 or 8 points per edge: every path is shorter than its arc, by 0.32% to 0.87%.
  const Errors finest = errors(m, 0.31 * kFinest, 0, arc, 0.3);
  EXPECT_LT(finest.over, 0.0);
  EXPECT_GT(finest.under, -0.0105);
  // The faces lie inside the sphere, so a path can be shorter than its arc, but by no more
  // than the faces are deep (1.78% here).
  for (const Errors& e : {used, finest}) EXPECT_GE(e.under, inradius(m) - 1);
}

TEST(GeodesicIntegral, SeveralSourcesGiveTheDistanceAndIndexOfTheNearest) {
  const Mesh m = test::unit_square(12);
  const SurfaceGraph g = surface_graph(m, mesh_edges(m.F), integral_max_edge(m));
  const std::vector<int> sources = {0, 12 * 13 + 12, 6 * 13 + 3};
  std::vector<std::vector<float>> single(sources.size());
  for (std::size_t s = 0; s < sources.size(); ++s) shortest_paths(g, {sources[s]}, single[s]);
  std::vector<float> d;
  std::vector<int> nearest;
  shortest_paths(g, sources, d, &nearest);
  int ties = 0;
  for (int v = 0; v < g.nodes(); ++v) {
    std::vector<float> at;
    for (const auto& s : single) at.push_back(s[std::size_t(v)]);
    const int best = int(std::min_element(at.begin(), at.end()) - at.begin());
    EXPECT_FLOAT_EQ(d[std::size_t(v)], at[std::size_t(best)]) << v;
    std::sort(at.begin(), at.end());
    if (at[1] - at[0] < 1e-6f) {
      ++ties;  // on a bisector either source is right
      continue;
    }
    EXPECT_EQ(nearest[std::size_t(v)], best) << v;
  }
  EXPECT_LT(ties, g.nodes() / 10);
}

TEST(GeodesicIntegral, LengthsRoundedForTheBucketQueueChangeDistancesLittle) {
  // mu sums these quantised distances, in the refinement the integral picks.
  const Mesh plane = test::unit_square(10), tube = test::open_tube(25, 24, 0.5, 3),
             sphere = test::icosphere(2);
  for (const Mesh* m : {&plane, &tube, &sphere}) {
    const SurfaceGraph g = surface_graph(*m, mesh_edges(m->F), integral_max_edge(*m));
    BucketScratch scratch;
    prepare_buckets(g, scratch);
    double worst = 0;
    for (int source = 0; source < int(m->V.rows()); source += 17) {
      std::vector<float> exact, rounded;
      shortest_paths(g, {source}, exact);
      shortest_paths_quantised(g, source, rounded, scratch);
      for (int v = 0; v < g.nodes(); ++v) {
        const double d = exact[std::size_t(v)], q = rounded[std::size_t(v)];
        if (d > 0.3) worst = std::max(worst, std::fabs(q - d) / d);
      }
    }
    // Measured: 1.30% (plane), 1.13% (tube), 1.73% (sphere).
    EXPECT_LT(worst, 0.021);
  }
}

TEST(GeodesicIntegral, ARunStoppedMidwayLeavesTheScratchReadyForTheNext) {
  // A stopped run leaves entries in the ring of buckets; the next run must not see them.
  const Mesh sphere = test::icosphere(5);  // 10,242 vertices: polled after 8,192 of them
  const SurfaceGraph g = surface_graph(sphere, mesh_edges(sphere.F), integral_max_edge(sphere));
  BucketScratch fresh, reused;
  prepare_buckets(g, fresh);
  prepare_buckets(g, reused);
  const StopRequested stop_soon = [] { return true; };
  std::vector<float> expected, got;
  EXPECT_THROW(shortest_paths_quantised(g, 0, got, reused, stop_soon), Interrupted);
  for (int source : {5, 700}) {
    shortest_paths_quantised(g, source, expected, fresh);
    shortest_paths_quantised(g, source, got, reused);
    EXPECT_EQ(got, expected) << source;
  }
}

TEST(GeodesicIntegral, WholeStepsGiveTheQuantisedDistancesExactly) {
  // mu reads shortest_steps' units through BucketScratch::distance; its bytes depend on that
  // being exactly what shortest_paths_quantised writes, unreached nodes included.
  Mesh two = test::icosphere(2);
  const Mesh other = test::icosphere(1);
  const Eigen::Index offset = two.V.rows();
  two.V.conservativeResize(offset + other.V.rows(), 3);
  two.V.bottomRows(other.V.rows()) = other.V.rowwise() + Eigen::RowVector3d(5, 0, 0);
  two.F.conservativeResize(two.F.rows() + other.F.rows(), 3);
  two.F.bottomRows(other.F.rows()) = other.F.array() + int(offset);
  SurfaceGraph g = surface_graph(two, mesh_edges(two.F), integral_max_edge(two));
  // Keep the two spheres apart: drop the links surface_graph adds between components.
  SurfaceGraph apart;
  apart.mesh_vertices = g.mesh_vertices;
  apart.offset.assign(g.offset.size(), 0);
  const auto side = [&](int node) { return node >= offset; };
  for (int v = 0; v < g.nodes(); ++v) {
    for (int k = g.offset[std::size_t(v)]; k < g.offset[std::size_t(v) + 1]; ++k) {
      const int w = g.target[std::size_t(k)];
      const bool keep = v >= g.mesh_vertices || w >= g.mesh_vertices || side(v) == side(w);
      if (!keep) continue;
      apart.target.push_back(w);
      apart.length.push_back(g.length[std::size_t(k)]);
    }
    apart.offset[std::size_t(v) + 1] = int(apart.target.size());
  }
  BucketScratch steps, floats;
  prepare_buckets(apart, steps);
  prepare_buckets(apart, floats);
  std::vector<float> expected;
  int unreached = 0;
  for (int source : {0, 3, int(offset) + 2}) {
    shortest_steps(apart, source, steps);
    shortest_paths_quantised(apart, source, expected, floats);
    ASSERT_EQ(steps.dist.size(), expected.size());
    for (std::size_t v = 0; v < expected.size(); ++v) {
      const float got = steps.distance(v);
      EXPECT_TRUE(got == expected[v] || (std::isinf(got) && std::isinf(expected[v]))) << v;
      EXPECT_EQ(steps.dist[v] == kUnreached, std::isinf(expected[v])) << v;
      unreached += steps.dist[v] == kUnreached;
    }
  }
  EXPECT_GT(unreached, 0);  // the other sphere, from each source
}

TEST(GeodesicIntegral, OnASphereTheIntegralIsTheSameAtEveryVertex) {
  // Exact: the integral of the arc length from any point over the unit sphere is 2 pi^2. With
  // 2 splits the integral's refinement adds a point per edge: spread 1.69%, mean 0.83% low.
  // With 3 the edges are already shorter than it asks for, so paths run along them and
  // overshoot the arcs (8% on average from one point): spread 2.74%, mean 5.23% high.
  struct Case {
    int splits;
    double spread, low, high;
  };
  for (const Case c : {Case{2, 0.021, -0.011, 0.0}, Case{3, 0.034, 0.04, 0.063}}) {
    const Mesh m = test::icosphere(c.splits);
    const std::vector<double> mu = geodesic_integral(m, mesh_edges(m.F), 128);
    const auto [lo, hi] = std::minmax_element(mu.begin(), mu.end());
    double mean = 0;
    for (double x : mu) mean += x;
    mean /= double(mu.size());
    EXPECT_LT((*hi - *lo) / mean, c.spread) << c.splits;
    EXPECT_GT(mean / (2 * M_PI * M_PI) - 1, c.low) << c.splits;
    EXPECT_LT(mean / (2 * M_PI * M_PI) - 1, c.high) << c.splits;
  }
}

TEST(GeodesicIntegral, NormalisingMapsTheRangeOntoZeroToOneAndAConstantToZero) {
  std::vector<double> mu = {3.0, 5.0, 4.0, 7.0};
  normalise_min_max(mu);
  EXPECT_EQ(mu, (std::vector<double>{0.0, 0.5, 0.25, 1.0}));
  std::vector<double> flat = {2.5, 2.5, 2.5};
  normalise_min_max(flat);
  EXPECT_EQ(flat, (std::vector<double>{0.0, 0.0, 0.0}));
}

TEST(GeodesicIntegral, TheBucketQueueIsExactOnTheQuantisedLengths) {
  // Every relaxation writes into its bucket and counts only an improvement: the distances must
  // be those of a heap Dijkstra over the same whole-unit lengths, to the unit.
  const Mesh tube = test::open_tube(25, 24, 0.5, 3), sphere = test::icosphere(4);
  for (const Mesh* m : {&tube, &sphere}) {
    SurfaceGraph g = surface_graph(*m, mesh_edges(m->F), integral_max_edge(*m));
    BucketScratch scratch;
    prepare_buckets(g, scratch);
    for (std::size_t k = 0; k < g.length.size(); ++k) g.length[k] = float(scratch.arc[k] >> 32);
    for (int source = 0; source < g.nodes(); source += 97) {
      std::vector<float> heap;
      shortest_paths(g, {source}, heap);
      shortest_steps(g, source, scratch);
      for (int v = 0; v < g.nodes(); ++v)
        ASSERT_EQ(double(scratch.dist[std::size_t(v)]), double(heap[std::size_t(v)]))
            << source << " -> " << v;
    }
  }
}
