// Tests for node_positions on a mesh built on a collapsed copy or a proxy: what surface is shown.
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

TEST(NodePositions, AModelBuiltOnItsProxyIsShownAsItselfWhenAsked) {
  // A sphere with a capsule through it: two pieces, so the build takes a watertight proxy.
  const Mesh ball = test::sphere(30, 40), rod = test::capsule(1.5, 0.3, 40, 16);
  Mesh soup;
  soup.V.resize(ball.V.rows() + rod.V.rows(), 3);
  soup.V << ball.V, rod.V.rowwise() + Eigen::RowVector3d(0, 0, 1.5);
  soup.F.resize(ball.F.rows() + rod.F.rows(), 3);
  soup.F << ball.F, rod.F.array() + int(ball.V.rows());
  const NodePositions built = node_positions(soup);
  ASSERT_TRUE(built.on_proxy);
  EXPECT_NE(built.mesh.F.rows(), soup.F.rows());  // the proxy

  const NodePositions own = node_positions(soup, {}, {}, ShownSurface::Own);
  ASSERT_TRUE(own.on_proxy);
  ASSERT_EQ(own.mesh.F.rows(), soup.F.rows());
  ASSERT_EQ(own.mu.size(), std::size_t(own.mesh.V.rows()));
  ASSERT_EQ(own.face_piece_begin.size(), std::size_t(own.mesh.F.rows()) + 1);
  // The graph and its barycentres are the proxy's.
  ASSERT_EQ(own.levels.size(), built.levels.size());
  for (std::size_t r = 0; r < own.levels.size(); ++r)
    EXPECT_EQ(own.levels[r].centre, built.levels[r].centre) << r;
  // Each vertex's mu is the nearest proxy vertex's; the rod's far tip, an end of the shape,
  // takes mu near the top of the range, as the proxy's tip does.
  Eigen::Index tip = 0;
  for (Eigen::Index v = 0; v < own.mesh.V.rows(); ++v) {
    double nearest = 1e300, mu = -1;
    for (Eigen::Index u = 0; u < built.mesh.V.rows(); ++u) {
      const double d = (built.mesh.V.row(u) - own.mesh.V.row(v)).squaredNorm();
      if (d < nearest) nearest = d, mu = built.mu[std::size_t(u)];
    }
    ASSERT_EQ(own.mu[std::size_t(v)], mu) << v;
    if (own.mesh.V.row(v).norm() > own.mesh.V.row(tip).norm()) tip = v;
  }
  EXPECT_GT(own.mu[std::size_t(tip)], 0.9);
  // Every face of the model's own surface belongs to a node at every level.
  for (int level = 0; level < int(own.levels.size()); ++level)
    for (Eigen::Index f = 0; f < own.mesh.F.rows(); ++f) {
      const double mu =
          (own.mu[std::size_t(own.mesh.F(f, 0))] + own.mu[std::size_t(own.mesh.F(f, 1))] +
           own.mu[std::size_t(own.mesh.F(f, 2))]) /
          3;
      const int node = node_at(own, level, int(f), mu);
      ASSERT_GE(node, 0) << level << " " << f;
      ASSERT_LT(std::size_t(node), own.levels[std::size_t(level)].area.size());
    }
}
