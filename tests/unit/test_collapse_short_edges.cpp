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

namespace {

// Every edge of a closed manifold lies on exactly two triangles, and no triangle repeats a
// corner; returns V - E + F.
int closed_euler_characteristic(const Mesh& m) {
  std::vector<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.F(f, k), b = m.F(f, (k + 1) % 3);
      EXPECT_NE(a, b) << "triangle " << f;
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    EXPECT_EQ(j - i, 2u) << "edge " << edges[i].first << "-" << edges[i].second;
    i = j;
  }
  return int(m.V.rows()) - int(edges.size() / 2) + int(m.F.rows());
}

}  // namespace

// Far collapses merge the faces around a vertex many times over (each survivor's list outgrows
// the room it started with): the surface stays closed, manifold and of its genus.
TEST(CollapseTopology, AFarCollapseKeepsGenusAndManifold) {
  CollapseOptions o;
  o.min_length = 0.5;
  const Mesh torus = test::torus(2, 0.6, 120, 45);
  const Mesh coarse_torus = collapse_short_edges(torus, o);
  EXPECT_LT(coarse_torus.F.rows(), torus.F.rows() / 10);
  EXPECT_EQ(closed_euler_characteristic(coarse_torus), 0);

  o.min_length = 0.4;
  const Mesh sphere = test::sphere(60, 80);  // poles of 80 triangles
  const Mesh coarse_sphere = collapse_short_edges(sphere, o);
  EXPECT_LT(coarse_sphere.F.rows(), sphere.F.rows() / 10);
  EXPECT_EQ(closed_euler_characteristic(coarse_sphere), 2);

  // A thin tube of four vertices around: without the link condition it pinches shut.
  o.min_length = 0.3;
  const Mesh tube = test::torus(2, 0.05, 200, 4);
  const Mesh coarse_tube = collapse_short_edges(tube, o);
  EXPECT_LT(coarse_tube.F.rows(), tube.F.rows() / 4);
  EXPECT_EQ(closed_euler_characteristic(coarse_tube), 0);
}

// Shortest first, ties by vertex index: the same mesh collapses to the same bytes every time.
TEST(CollapseTopology, TheSameMeshCollapsesTheSameWay) {
  CollapseOptions o;
  o.min_length = 0.3;
  const Mesh sphere = test::sphere(40, 50);
  const Mesh a = collapse_short_edges(sphere, o), b = collapse_short_edges(sphere, o);
  ASSERT_EQ(a.V.rows(), b.V.rows());
  ASSERT_EQ(a.F.rows(), b.F.rows());
  EXPECT_TRUE(a.V == b.V);
  EXPECT_TRUE(a.F == b.F);
}
