// Tests for node_positions on a mesh built on a collapsed copy: the fine surface is shown.
#include <gtest/gtest.h>

#include <vector>

#include "mesh/surface_area.hpp"
#include "pipeline/node_positions.hpp"
#include "pipeline/prepare_surface.hpp"
#include "reeb/slice_intervals.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

double triangle_area(const Mesh& m, Eigen::Index f) {
  const Eigen::RowVector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
  return 0.5 * (b - a).cross(c - a).norm();
}

}  // namespace

TEST(NodePositions, AMeshBuiltOnACollapsedCopyIsShownOnItsFineSurface) {
  // 100,000 triangles, 50,000 vertices: far above kCoarseAbove, collapsed to ~30,000.
  const Mesh torus = test::torus(2, 0.6, 400, 125);
  ASSERT_GT(torus.V.rows(), kCoarseAbove);
  const NodePositions p = node_positions(torus);
  ASSERT_EQ(p.mesh.F.rows(), torus.F.rows());
  ASSERT_EQ(p.mu.size(), std::size_t(p.mesh.V.rows()));
  ASSERT_EQ(p.face_piece_begin.size(), std::size_t(p.mesh.F.rows()) + 1);
  ASSERT_EQ(p.face_first_interval.size(), std::size_t(p.mesh.F.rows()));
  for (double m : p.mu) ASSERT_TRUE(m >= 0 && m <= 1);

  // Every triangle's centre belongs to a node; nearly always one of its own mu interval (a
  // triangle the collapse removed takes the pieces of a neighbour), and the nodes' shares of
  // the fine surface are those the copy gave them.
  const int level = 3, intervals = 1 << level;
  const std::vector<double>& share = p.levels[std::size_t(level)].area;
  std::vector<double> area(share.size(), 0.0);
  double total = 0;
  std::size_t same = 0;
  for (Eigen::Index f = 0; f < p.mesh.F.rows(); ++f) {
    const double mu = (p.mu[std::size_t(p.mesh.F(f, 0))] + p.mu[std::size_t(p.mesh.F(f, 1))] +
                       p.mu[std::size_t(p.mesh.F(f, 2))]) /
                      3;
    const int node = node_at(p, level, int(f), mu);
    ASSERT_GE(node, 0) << f;
    ASSERT_LT(std::size_t(node), share.size()) << f;
    same += p.levels[std::size_t(level)].interval[std::size_t(node)] == interval_of(mu, intervals);
    const double a = triangle_area(p.mesh, f);
    area[std::size_t(node)] += a;
    total += a;
  }
  EXPECT_GT(double(same), 0.99 * double(p.mesh.F.rows()));
  for (std::size_t i = 0; i < share.size(); ++i) EXPECT_NEAR(area[i] / total, share[i], 0.01) << i;
}

TEST(NodePositions, AMeshUnderTheThresholdIsShownAsBuilt) {
  const Mesh torus = test::torus();  // 2,400 vertices
  ASSERT_LE(torus.V.rows(), kCoarseAbove);
  const NodePositions p = node_positions(torus);
  EXPECT_EQ(p.mesh.F.rows(), torus.F.rows());
  EXPECT_EQ(p.piece_node.size(), std::size_t(p.face_piece_begin.back()));
}
