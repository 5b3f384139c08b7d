// Restriction: a fine mesh's vertex positions carried to its collapsed copy's vertices.
#include <gtest/gtest.h>

#include "mesh/collapse_short_edges.hpp"
#include "mesh/mesh_edges.hpp"
#include "mesh/restrict_vertex_positions.hpp"
#include "mesh/taubin_smoothing.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

struct Collapsed {
  Mesh fine, coarse;
  std::vector<int> map;
};

Collapsed collapsed_torus() {
  Collapsed c;
  c.fine = test::torus(2, 0.6, 120, 45);
  CollapseOptions o;
  o.min_length = 0.2;
  c.coarse = collapse_short_edges(c.fine, o, {}, &c.map);
  return c;
}

}  // namespace

TEST(RestrictVertexPositions, EachCopyVertexIsTheMeanOfWhatItGathered) {
  const Collapsed c = collapsed_torus();
  ASSERT_LT(c.coarse.V.rows(), c.fine.V.rows() / 3);
  // A field that is not affine in the position, so a mean differs from a value at one point.
  Vertices moved = c.fine.V;
  for (Eigen::Index v = 0; v < moved.rows(); ++v) moved(v, 2) += double(v % 7);
  const Mesh out = restrict_vertex_positions(c.coarse, c.map, moved);
  ASSERT_EQ(out.V.rows(), c.coarse.V.rows());
  EXPECT_TRUE(out.F == c.coarse.F);
  Vertices sum = Vertices::Zero(c.coarse.V.rows(), 3);
  std::vector<int> count(std::size_t(c.coarse.V.rows()), 0);
  for (std::size_t v = 0; v < c.map.size(); ++v) {
    ASSERT_GE(c.map[v], 0);
    sum.row(c.map[v]) += moved.row(Eigen::Index(v));
    ++count[std::size_t(c.map[v])];
  }
  for (Eigen::Index k = 0; k < out.V.rows(); ++k) {
    ASSERT_GT(count[std::size_t(k)], 0);
    EXPECT_LT((out.V.row(k) - sum.row(k) / count[std::size_t(k)]).norm(), 1e-12) << k;
  }
}

TEST(RestrictVertexPositions, TheFinePositionsGiveTheCopyBack) {
  // The copy's vertices are midpoints of what they gathered: the fine positions themselves
  // land within a collapse length of them.
  const Collapsed c = collapsed_torus();
  const Mesh out = restrict_vertex_positions(c.coarse, c.map, c.fine.V);
  for (Eigen::Index k = 0; k < out.V.rows(); ++k)
    EXPECT_LT((out.V.row(k) - c.coarse.V.row(k)).norm(), 0.2) << k;
}

TEST(RestrictVertexPositions, AVertexNothingMapsToKeepsItsPlace) {
  const Collapsed c = collapsed_torus();
  const std::vector<int> unmapped(c.map.size(), -1);
  const Mesh out = restrict_vertex_positions(c.coarse, unmapped, c.fine.V);
  EXPECT_TRUE(out.V == c.coarse.V);
}

TEST(RestrictVertexPositions, SmoothedFinePositionsLieOnTheSmoothedSurface) {
  // What the views take on a copy: the smoothed fine surface, restricted, stays within a
  // collapse length of the copy (smoothing moves a torus of this size very little).
  const Collapsed c = collapsed_torus();
  const Mesh smooth = taubin_smoothing(c.fine, mesh_edges(c.fine.F), 80, 0.5, -0.53, {});
  const Mesh out = restrict_vertex_positions(c.coarse, c.map, smooth.V);
  for (Eigen::Index k = 0; k < out.V.rows(); ++k)
    EXPECT_LT((out.V.row(k) - c.coarse.V.row(k)).norm(), 0.25) << k;
}
