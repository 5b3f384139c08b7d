// Pooling: a fragmented graph's smallest components pooled, its largest kept whole.
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "pipeline/build_arg.hpp"
#include "pipeline/pool_fragments.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

// A graph of `levels` levels: one large component with a node on every interval of every level,
// linked along mu, and `small` components of one node a level, each on its own path of
// intervals. Every level's areas sum to 1/(levels + 1); histograms sum to the areas.
ArgGraph fragmented(int levels, int small) {
  ArgGraph g;
  g.options.levels = levels;
  const double per_level = 1.0 / (levels + 1);
  const double big_share = 0.6, small_area = per_level * (1 - big_share) / small;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  std::vector<std::uint32_t> big_prev, small_prev;
  g.level_begin.assign(std::size_t(levels) + 2, 0);
  for (int r = 0; r <= levels; ++r) {
    const std::uint32_t intervals = 1u << r;
    std::vector<std::uint32_t> big, smalls(std::size_t(small), 0);
    // Nodes sorted by interval: the big component's node first, then the small ones there.
    for (std::uint32_t t = 0; t < intervals; ++t) {
      ArgNode n;
      n.level = std::uint16_t(r), n.interval = std::uint16_t(t);
      n.parent = r == 0 ? -1 : std::int32_t(big_prev[t / 2]);
      n.a = float(per_level * big_share / intervals), n.l = float(per_level / intervals);
      n.r = 1, n.theta = 0.2f, n.phi = 1;
      n.mu_min = float(t) / intervals, n.mu_max = float(t + 1) / intervals;
      n.cords[0] = n.curv_mean[1] = n.curv_gauss[2] = n.a;
      if (t > 0)
        edges.push_back({std::uint32_t(g.nodes.size()) - 1, std::uint32_t(g.nodes.size())});
      big.push_back(std::uint32_t(g.nodes.size()));
      g.nodes.push_back(n);
      // Small ones whose path passes through this interval (skipping the big node before them).
      for (int c = 0; c < small; ++c) {
        const std::uint32_t finest = std::uint32_t(c) % (1u << levels);
        if ((finest >> (levels - r)) != t) continue;
        ArgNode m = n;
        m.parent = r == 0 ? -1 : std::int32_t(small_prev[std::size_t(c)]);
        m.a = float(small_area), m.l = float(small_area);
        m.r = 0.5f + 0.01f * float(c % 50), m.theta = -0.3f, m.phi = 2;
        m.cords = {}, m.curv_mean = {}, m.curv_gauss = {};
        m.cords[3] = m.curv_mean[4] = m.curv_gauss[5] = m.a;
        smalls[std::size_t(c)] = std::uint32_t(g.nodes.size());
        g.nodes.push_back(m);
      }
    }
    big_prev = big, small_prev = smalls;
    g.level_begin[std::size_t(r) + 1] = std::uint32_t(g.nodes.size());
  }
  link_graph(g, edges);
  return g;
}

double level_area(const ArgGraph& g, int r) {
  double a = 0;
  for (std::uint32_t i = g.level_begin[std::size_t(r)]; i < g.level_begin[std::size_t(r) + 1]; ++i)
    a += g.nodes[i].a;
  return a;
}

TEST(PoolFragments, AGraphWithinTheBoundIsLeftAsItIs) {
  ArgGraph g = fragmented(3, 10);
  const std::string before = serialize_arg(g);
  EXPECT_EQ(pool_fragments(g, 100), 0u);
  EXPECT_EQ(serialize_arg(g), before);
  EXPECT_FALSE(g.summary.flags & kFlagPooled);
}

TEST(PoolFragments, EveryLevelEndsWithinTheBoundWithItsAreaKept) {
  const int levels = 4;
  const std::size_t bound = 60;
  ArgGraph g = fragmented(levels, 300);
  ASSERT_GT(g.level_begin[1], bound) << "300 components on level 0";
  ArgGraph too_many = fragmented(levels, 2000);
  EXPECT_THROW(serialize_arg(too_many), InputError) << "format 3 refuses a graph over the bound";
  too_many.format = 2;
  EXPECT_NO_THROW(serialize_arg(too_many)) << "format 2 has no bound";
  const ArgGraph before = g;
  const std::size_t pooled = pool_fragments(g, bound);
  EXPECT_GT(pooled, 0u);
  EXPECT_LE(pooled, 300u);
  EXPECT_TRUE(g.summary.flags & kFlagPooled);
  EXPECT_EQ(g.summary.pooled, pooled);
  for (int r = 0; r <= levels; ++r) {
    EXPECT_LE(g.level_begin[std::size_t(r) + 1] - g.level_begin[std::size_t(r)], bound);
    EXPECT_NEAR(level_area(g, r), level_area(before, r), 1e-6) << "level " << r;
  }
  // The largest component is kept whole: level 0's largest node is its node as it was.
  float largest = 0;
  for (std::uint32_t i = 0; i < g.level_begin[1]; ++i) largest = std::max(largest, g.nodes[i].a);
  EXPECT_FLOAT_EQ(largest, before.nodes[0].a);
  // A pooled node's histograms still sum to its area, and the whole is a valid format-3 graph.
  for (const ArgNode& n : g.nodes) {
    double sum = 0;
    for (float x : n.cords) sum += x;
    EXPECT_NEAR(sum, n.a, 1e-6);
  }
  const std::string bytes = serialize_arg(g);
  const ArgGraph back = deserialize_arg(bytes);
  EXPECT_EQ(back.summary.pooled, pooled);
  EXPECT_EQ(serialize_arg(back), bytes);
  EXPECT_EQ(arg_similarity(back, stored_form(g)), 0.0);
}

TEST(PoolFragments, AScatterOfThousandsOfPartsBuildsUnderTheSizeBound) {
  // 3,000 small separate triangles: a node per part on every level before pooling.
  Mesh m;
  const int parts = 3000;
  m.V.resize(3 * parts, 3);
  m.F.resize(parts, 3);
  for (int p = 0; p < parts; ++p) {
    const double x = p % 30, y = (p / 30) % 10, z = p / 300;
    for (int k = 0; k < 3; ++k) {
      m.V.row(3 * p + k) << x + 0.4 * (k == 1), y + 0.4 * (k == 2), z + 0.1 * std::sin(p + k);
      m.F(p, k) = 3 * p + k;
    }
  }
  BuildOptions mesh_surface;
  mesh_surface.surface = SurfaceKind::Mesh;
  const ArgGraph g = build_arg(m, mesh_surface);
  EXPECT_TRUE(g.summary.flags & kFlagPooled);
  EXPECT_GT(g.summary.pooled, 0);
  for (int r = 0; r <= g.levels(); ++r)
    EXPECT_LE(g.level_begin[std::size_t(r) + 1] - g.level_begin[std::size_t(r)], 640u);
  EXPECT_LE(serialize_arg(g).size(), 256u * 1000u);
}

}  // namespace
}  // namespace arg
