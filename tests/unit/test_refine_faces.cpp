// Conforming refinement of faces near a point: same surface, no cracks, nothing far changed.
#include <gtest/gtest.h>

#include "eval/refine_faces.hpp"
#include "mesh/clean_mesh.hpp"
#include "mesh/surface_area.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

// Near: a corner or the centre within `reach` of p (coarser than the hole's exact distance).
auto near_point(const Eigen::RowVector3d& p, double reach) {
  return [p, reach](const Eigen::RowVector3d& a, const Eigen::RowVector3d& b,
                    const Eigen::RowVector3d& c) {
    return (a - p).norm() < reach || (b - p).norm() < reach || (c - p).norm() < reach ||
           ((a + b + c) / 3.0 - p).norm() < reach;
  };
}

double longest_edge_near(const Mesh& m, const Eigen::RowVector3d& p, double reach) {
  double longest = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      const Eigen::RowVector3d a = m.V.row(m.F(f, c)), b = m.V.row(m.F(f, (c + 1) % 3));
      if ((a - p).norm() < 0.5 * reach && (b - p).norm() < 0.5 * reach)
        longest = std::max(longest, (a - b).norm());
    }
  return longest;
}

TEST(RefineFaces, AClosedCoarseSurfaceStaysClosedWithTheSameAreaAndFineEdgesNearThePoint) {
  const Mesh coarse = test::capsule(2, 0.6, 10, 8);
  const Eigen::RowVector3d p = coarse.V.row(7);
  for (const Mesh& input : {coarse, test::unwelded(coarse)}) {
    const Mesh fine = refine_faces(input, 0.05, near_point(p, 0.3), 1000000);
    EXPECT_GT(fine.F.rows(), 4 * coarse.F.rows());
    EXPECT_NEAR(surface_area(fine), surface_area(coarse), 1e-9 * surface_area(coarse));
    EXPECT_LE(longest_edge_near(fine, p, 0.3), 0.05);
    CleanReport report;
    clean_mesh(fine, &report);  // welds the soup's corners: a T-junction would leave a rim
    EXPECT_EQ(report.boundary_edges, 0u);
    // Every face turns as its neighbours do (cleaning may turn the whole surface outwards).
    EXPECT_TRUE(report.flipped_faces == 0 || report.flipped_faces == std::size_t(fine.F.rows()))
        << report.flipped_faces;
  }
}

TEST(RefineFaces, FacesFarFromThePointAreKeptAndTheFaceBudgetHolds) {
  const Mesh coarse = test::capsule(2, 0.6, 10, 8);
  const Eigen::RowVector3d far(100, 100, 100);
  const Mesh same = refine_faces(coarse, 0.01, near_point(far, 1), 1000000);
  EXPECT_TRUE(same.F == coarse.F);
  EXPECT_TRUE(same.V == coarse.V);
  // A budget stops refining before a pass would pass it.
  const Mesh capped =
      refine_faces(coarse, 1e-4, near_point(coarse.V.row(7), 10), 5 * coarse.F.rows());
  EXPECT_LE(capped.F.rows(), 5 * coarse.F.rows());
  EXPECT_GT(capped.F.rows(), coarse.F.rows());
  // Every face keeps the colour of the face it was cut from.
  Mesh painted = coarse;
  painted.C.resize(coarse.F.rows(), 3);
  for (Eigen::Index f = 0; f < coarse.F.rows(); ++f)
    painted.C.row(f) << float(f) / float(coarse.F.rows()), 0.5f, 0.25f;
  const Mesh fine = refine_faces(painted, 0.05, near_point(coarse.V.row(7), 0.3), 1000000);
  ASSERT_TRUE(fine.has_colour());
  for (Eigen::Index f = 0; f < fine.F.rows(); ++f) {
    const Eigen::RowVector3d centre =
        (fine.V.row(fine.F(f, 0)) + fine.V.row(fine.F(f, 1)) + fine.V.row(fine.F(f, 2))) / 3.0;
    // The input face whose plane holds the centre and which holds it inside (barycentric).
    Eigen::Index from = -1;
    for (Eigen::Index g = 0; g < coarse.F.rows() && from < 0; ++g) {
      const Eigen::RowVector3d a = coarse.V.row(coarse.F(g, 0)), b = coarse.V.row(coarse.F(g, 1)),
                               c = coarse.V.row(coarse.F(g, 2));
      const Eigen::RowVector3d n = (b - a).cross(c - a);
      if (std::fabs((centre - a).dot(n.normalized())) > 1e-9) continue;
      const double u = (b - centre).cross(c - centre).dot(n),
                   v = (c - centre).cross(a - centre).dot(n),
                   w = (a - centre).cross(b - centre).dot(n);
      if (u >= 0 && v >= 0 && w >= 0) from = g;
    }
    ASSERT_GE(from, 0) << f;
    EXPECT_EQ(fine.C.row(f), painted.C.row(from)) << f;
  }
}

}  // namespace
}  // namespace arg
