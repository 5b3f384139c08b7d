// The Reeb graph's levels built directly from sliced meshes: merging, areas, and chains.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "mesh/mesh_edges.hpp"
#include "mu/mu_function.hpp"
#include "reeb/reeb_levels.hpp"
#include "reeb/slice_intervals.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

struct Sliced {
  SlicedSurface surface;
  ReebGraph reeb;
};

Sliced slice(const Mesh& m, const std::vector<double>& mu, int levels) {
  Sliced s;
  s.surface = slice_intervals(m, mu, 1 << levels);
  s.reeb = reeb_levels(s.surface, mesh_edges(m.F), levels);
  return s;
}

// mu = coordinate `axis` mapped onto [0, 1].
std::vector<double> height(const Mesh& m, int axis) {
  std::vector<double> mu(std::size_t(m.V.rows()));
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) mu[std::size_t(v)] = m.V(v, axis);
  normalise_min_max(mu);
  return mu;
}

// Area of every node of every level, from the pieces of the finest level up the parent links.
std::vector<std::vector<double>> node_areas(const Sliced& s) {
  const int levels = int(s.reeb.levels.size()) - 1;
  std::vector<std::vector<double>> area(s.reeb.levels.size());
  for (int r = 0; r <= levels; ++r)
    area[std::size_t(r)].assign(s.reeb.levels[std::size_t(r)].interval.size(), 0.0);
  for (std::size_t p = 0; p < s.surface.pieces.size(); ++p)
    area[std::size_t(levels)][std::size_t(s.reeb.piece_node[p])] += s.surface.pieces[p].area;
  for (int r = levels; r > 0; --r) {
    const ReebLevel& child = s.reeb.levels[std::size_t(r)];
    for (std::size_t i = 0; i < child.parent.size(); ++i)
      area[std::size_t(r) - 1][std::size_t(child.parent[i])] += area[std::size_t(r)][i];
  }
  return area;
}

// Node degrees of one level.
std::vector<int> degrees(const ReebLevel& level) {
  std::vector<int> d(level.interval.size(), 0);
  for (auto [i, j] : level.edges) ++d[std::size_t(i)], ++d[std::size_t(j)];
  return d;
}

// Whether the level's nodes form one simple path.
bool is_one_path(const ReebLevel& level) {
  const std::size_t n = level.interval.size();
  if (level.edges.size() + 1 != n) return false;
  std::vector<int> component(n);
  std::iota(component.begin(), component.end(), 0);
  auto find = [&](int x) {
    while (component[std::size_t(x)] != x) x = component[std::size_t(x)];
    return x;
  };
  for (auto [i, j] : level.edges) component[std::size_t(find(i))] = find(j);
  int roots = 0;
  for (std::size_t i = 0; i < n; ++i) roots += find(int(i)) == int(i);
  const std::vector<int> d = degrees(level);
  return roots == 1 && *std::max_element(d.begin(), d.end()) <= 2;
}

}  // namespace

TEST(ReebLevels, CoarserLevelsMergeConnectedChildrenOfIntervalPairs) {
  // A torus lying flat, sliced along x: two branches between the inner saddles.
  const Mesh torus = test::torus();
  const Sliced s = slice(torus, height(torus, 0), 5);
  const auto& levels = s.reeb.levels;
  for (int r = 0; r + 1 < int(levels.size()); ++r) {
    const ReebLevel& parent = levels[std::size_t(r)];
    const ReebLevel& child = levels[std::size_t(r) + 1];
    // Intervals at level r are 0 .. 2^r - 1, all present, in order: their count halves.
    std::vector<int> present = parent.interval;
    present.erase(std::unique(present.begin(), present.end()), present.end());
    std::vector<int> all(std::size_t(1) << r);
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(present, all) << "level " << r;
    for (std::size_t i = 0; i < child.parent.size(); ++i)
      EXPECT_EQ(parent.interval[std::size_t(child.parent[i])], child.interval[i] / 2);
    // Two children of one interval pair share a parent exactly when edges within the pair
    // join them.
    const std::size_t n = child.interval.size();
    std::vector<int> group(n);
    std::iota(group.begin(), group.end(), 0);
    for (bool changed = true; changed;) {
      changed = false;
      for (auto [i, j] : child.edges) {
        if (child.interval[std::size_t(i)] / 2 != child.interval[std::size_t(j)] / 2) continue;
        const int low = std::min(group[std::size_t(i)], group[std::size_t(j)]);
        changed |= group[std::size_t(i)] != low || group[std::size_t(j)] != low;
        group[std::size_t(i)] = group[std::size_t(j)] = low;
      }
    }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (child.interval[i] / 2 == child.interval[j] / 2) {
          EXPECT_EQ(child.parent[i] == child.parent[j], group[i] == group[j])
              << "level " << r + 1 << " nodes " << i << " " << j;
        }
    // Edges join neighbouring intervals only.
    for (auto [i, j] : parent.edges)
      EXPECT_EQ(std::abs(parent.interval[std::size_t(i)] - parent.interval[std::size_t(j)]), 1);
  }
  // Between the saddles at x = +-1.4 of x in [-2.6, 2.6] an interval holds two nodes.
  const double s1 = 1.2 / 5.2, s2 = 4.0 / 5.2;
  for (int r = 0; r < int(levels.size()); ++r) {
    const int intervals = 1 << r;
    for (int k = 0; k < intervals; ++k) {
      const bool between = double(k) / intervals > s1 && double(k + 1) / intervals < s2;
      const auto count = std::count(levels[std::size_t(r)].interval.begin(),
                                    levels[std::size_t(r)].interval.end(), k);
      EXPECT_EQ(count, between ? 2 : 1) << "level " << r << " interval " << k;
    }
  }
  EXPECT_EQ(s.reeb.loops, 1);
}

TEST(ReebLevels, ParentAreasSumTheirChildrenToWhatACoarserSlicingGives) {
  // Level r of a 5-level graph is the surface sliced into 2^r intervals: the same nodes with
  // the same areas (the sum of their children's) and the same edges.
  const Mesh torus = test::torus();
  const std::vector<double> mu = height(torus, 0);
  const int levels = 5;
  const Sliced fine = slice(torus, mu, levels);
  const auto area = node_areas(fine);
  const double total = std::accumulate(area[0].begin(), area[0].end(), 0.0);
  for (int r = 0; r < levels; ++r) {
    const Sliced coarse = slice(torus, mu, r);
    const std::vector<double> coarse_area = node_areas(coarse)[std::size_t(r)];
    const ReebLevel& a = fine.reeb.levels[std::size_t(r)];
    const ReebLevel& b = coarse.reeb.levels[std::size_t(r)];
    ASSERT_EQ(a.interval, b.interval) << "level " << r;
    EXPECT_EQ(a.edges.size(), b.edges.size()) << "level " << r;
    // Nodes of one interval may be numbered apart: compare each interval's sorted areas.
    for (int k = 0; k < 1 << r; ++k) {
      std::vector<double> x, y;
      for (std::size_t i = 0; i < a.interval.size(); ++i)
        if (a.interval[i] == k) x.push_back(area[std::size_t(r)][i]), y.push_back(coarse_area[i]);
      std::sort(x.begin(), x.end()), std::sort(y.begin(), y.end());
      for (std::size_t i = 0; i < x.size(); ++i)
        EXPECT_NEAR(x[i], y[i], 1e-12 * total) << "level " << r << " interval " << k;
    }
  }
}

TEST(ReebLevels, ATubeSlicedByHeightIsAChainOfBandsOfExactArea) {
  // A capsule along z, sliced by height: one node per interval, a chain, and where the
  // intervals lie on the straight tube, each band's area is the prism's perimeter x height.
  const double h = 3, radius = 0.5;
  const int cols = 32, levels = 3;
  const Mesh m = test::capsule(h, radius, 90, cols);
  const Sliced s = slice(m, height(m, 2), levels);
  const auto area = node_areas(s);
  const double total = std::accumulate(area[0].begin(), area[0].end(), 0.0);
  for (int r = 0; r <= levels; ++r) {
    const ReebLevel& level = s.reeb.levels[std::size_t(r)];
    ASSERT_EQ(level.interval.size(), std::size_t(1) << r);
    EXPECT_TRUE(is_one_path(level)) << "level " << r;
    // Each node holds exactly the pieces of its intervals at the finest level.
    for (std::size_t i = 0; i < level.interval.size(); ++i) {
      double direct = 0;
      for (const Piece& p : s.surface.pieces)
        if (p.interval >> (levels - r) == level.interval[i]) direct += p.area;
      EXPECT_NEAR(area[std::size_t(r)][i], direct, 1e-12 * total) << "level " << r;
    }
  }
  const double perimeter = cols * 2 * radius * std::sin(M_PI / cols);
  const double band = 2 * (h + radius) / (1 << levels);
  const ReebLevel& finest = s.reeb.levels[std::size_t(levels)];
  for (std::size_t i = 0; i < finest.interval.size(); ++i) {
    const int k = finest.interval[i];
    const double z0 = -(h + radius) + k * band;
    if (z0 >= -h && z0 + band <= h) {
      EXPECT_NEAR(area[std::size_t(levels)][i], perimeter * band, 1e-9) << "interval " << k;
    }
  }
}

TEST(ReebLevels, AShapeWithTwoEndsIsAChainFoldedAtItsMiddle) {
  // The geodesic integral is least around the middle of a capsule and grows towards both
  // ends: the middle band is one node, every interval above it two, one towards each end.
  // Four levels, not the default five: at five each tip gains a spurious node, because mu
  // peaks on a ring three rows below the pole, not at it (edge paths from the pole run along
  // the meridians, those from the ring cross the grid's diagonals and come out too long).
  const Mesh m = test::capsule();
  std::vector<double> mu = geodesic_integral(m, mesh_edges(m.F), 128);
  normalise_min_max(mu);
  const int levels = 4;
  const Sliced s = slice(m, mu, levels);
  for (int r = 0; r <= levels; ++r) {
    const ReebLevel& level = s.reeb.levels[std::size_t(r)];
    const int intervals = 1 << r;
    EXPECT_EQ(level.interval.size(), std::size_t(2 * intervals - 1)) << "level " << r;
    EXPECT_EQ(std::count(level.interval.begin(), level.interval.end(), 0), 1) << "level " << r;
    EXPECT_TRUE(is_one_path(level)) << "level " << r;
    // Its two ends are the capsule's tips, in the top interval.
    const std::vector<int> d = degrees(level);
    for (std::size_t i = 0; i < d.size(); ++i)
      if (d[i] < 2 && r > 0) {
        EXPECT_EQ(level.interval[i], intervals - 1) << "level " << r;
      }
    EXPECT_EQ(std::count(d.begin(), d.end(), 1), r > 0 ? 2 : 0) << "level " << r;
  }
  EXPECT_EQ(s.reeb.loops, 0);
}
