// Restriction: triangle values of a fine mesh averaged onto its collapsed copy's triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "collapsed_torus.hpp"
#include "mesh/collapse_short_edges.hpp"
#include "mesh/restrict_face_values.hpp"

using namespace arg;

namespace {

Eigen::Vector3d centroid(const Mesh& m, Eigen::Index f) {
  return (m.V.row(m.F(f, 0)) + m.V.row(m.F(f, 1)) + m.V.row(m.F(f, 2))).transpose() / 3;
}

}  // namespace

TEST(RestrictFaceValues, AConstantStaysConstant) {
  const test::Collapsed c = test::collapsed_torus();
  ASSERT_LT(c.coarse.F.rows(), c.fine.F.rows() / 3);
  const std::vector<double> fine(std::size_t(c.fine.F.rows()), 2.5);
  const std::vector<double> out = restrict_face_values(c.fine, c.coarse, c.map, fine);
  ASSERT_EQ(out.size(), std::size_t(c.coarse.F.rows()));
  for (double v : out) EXPECT_NEAR(v, 2.5, 1e-12);
}

TEST(RestrictFaceValues, AFieldKeepsItsRangeAndFollowsTheSurface) {
  const test::Collapsed c = test::collapsed_torus();
  std::vector<double> fine;
  for (Eigen::Index f = 0; f < c.fine.F.rows(); ++f) fine.push_back(centroid(c.fine, f).x());
  const std::vector<double> out = restrict_face_values(c.fine, c.coarse, c.map, fine);
  const auto [lo, hi] = std::minmax_element(fine.begin(), fine.end());
  for (Eigen::Index f = 0; f < c.coarse.F.rows(); ++f) {
    EXPECT_GE(out[std::size_t(f)], *lo - 1e-12);
    EXPECT_LE(out[std::size_t(f)], *hi + 1e-12);
    // Averaged over about two rings of fine triangles, within a few collapse lengths.
    EXPECT_NEAR(out[std::size_t(f)], centroid(c.coarse, f).x(), 0.4) << f;
  }
}

TEST(RestrictFaceValues, AVertexNoFineTriangleReachedCountsZero) {
  const test::Collapsed c = test::collapsed_torus();
  const std::vector<double> fine(std::size_t(c.fine.F.rows()), 1.0);
  const std::vector<int> unmapped(c.map.size(), -1);
  for (double v : restrict_face_values(c.fine, c.coarse, unmapped, fine)) EXPECT_EQ(v, 0.0);
}
