// Collapsing short edges: each removed vertex is mapped to its survivor, colours stay put.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "collapsed_torus.hpp"
#include "mesh/collapse_short_edges.hpp"

using namespace arg;

TEST(CollapseVertexMap, EveryVertexGoesToANearbySurvivor) {
  const test::Collapsed c = test::collapsed_torus();
  ASSERT_LT(c.coarse.V.rows(), c.fine.V.rows() / 3);
  ASSERT_EQ(c.map.size(), std::size_t(c.fine.V.rows()));
  std::vector<int> hits(std::size_t(c.coarse.V.rows()), 0);
  for (Eigen::Index v = 0; v < c.fine.V.rows(); ++v) {
    const int to = c.map[std::size_t(v)];
    ASSERT_GE(to, 0);
    ASSERT_LT(to, c.coarse.V.rows());
    ++hits[std::size_t(to)];
    // A vertex moves at most a few collapse lengths.
    EXPECT_LT((c.fine.V.row(v) - c.coarse.V.row(to)).norm(), 0.6) << v;
  }
  // Every coarse vertex is where at least one fine vertex went.
  EXPECT_EQ(std::count(hits.begin(), hits.end(), 0), 0);
}

TEST(CollapseVertexMap, SurvivingTrianglesKeepTheirColour) {
  Mesh fine = test::sphere(30, 40);
  fine.C.resize(fine.F.rows(), 3);
  for (Eigen::Index f = 0; f < fine.F.rows(); ++f) {
    const double z = (fine.V.row(fine.F(f, 0)) + fine.V.row(fine.F(f, 1))).z() / 2;
    fine.C.row(f) << float(z > 0), 0.5f, float(z <= 0);
  }
  CollapseOptions o;
  o.min_length = 0.15;
  const Mesh coarse = collapse_short_edges(fine, o);
  ASSERT_LT(coarse.F.rows(), fine.F.rows());
  ASSERT_TRUE(coarse.has_colour());
  // Far from the equator each triangle keeps the colour of its hemisphere.
  for (Eigen::Index f = 0; f < coarse.F.rows(); ++f) {
    const double z =
        (coarse.V.row(coarse.F(f, 0)) + coarse.V.row(coarse.F(f, 1)) + coarse.V.row(coarse.F(f, 2)))
            .z() /
        3;
    if (std::abs(z) < 0.3) continue;
    EXPECT_EQ(coarse.C(f, 0), z > 0 ? 1.0f : 0.0f) << f;
    EXPECT_EQ(coarse.C(f, 1), 0.5f);
  }
}
