// Quadric decimation of the robustness benchmark: the budget, the shape, what it cannot hold.
#include <gtest/gtest.h>

#include "eval/quadric_decimation.hpp"
#include "mesh/surface_area.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

TEST(QuadricDecimation, ReachesTheBudgetAndKeepsTheShape) {
  const Mesh capsule = test::capsule(2, 0.6, 60, 32);
  const Mesh out = quadric_decimation(capsule, std::size_t(capsule.V.rows() / 4));
  EXPECT_LE(out.V.rows(), capsule.V.rows() / 4);
  EXPECT_NEAR(surface_area(out), surface_area(capsule), 0.03 * surface_area(capsule));
  EXPECT_EQ(quadric_decimation(capsule, 1000000).F.rows(), capsule.F.rows());  // nothing to do
}

TEST(QuadricDecimation, FacesItCannotHoldAreKeptAsTheyWere) {
  // A capsule with a fin (a third face on one of its edges) and a face with a repeated corner.
  Mesh m = test::capsule(2, 0.6, 30, 16);
  const Eigen::Index nv = m.V.rows(), nf = m.F.rows();
  const int a = m.F(0, 0), b = m.F(0, 1);
  m.V.conservativeResize(nv + 1, 3);
  m.V.row(nv) = m.V.row(a) + Eigen::RowVector3d(5, 5, 5);
  m.F.conservativeResize(nf + 2, 3);
  m.F.row(nf) << a, b, int(nv);
  m.F.row(nf + 1) << a, a, b;
  const std::size_t target = std::size_t(m.V.rows() / 3);
  const Mesh out = quadric_decimation(m, target);
  // The two odd faces come back with corners of their own, the rest is decimated to the budget.
  EXPECT_LE(out.V.rows(), Eigen::Index(target) + 6);
  EXPECT_LT(out.F.rows(), nf);
  bool fin = false;
  for (Eigen::Index f = 0; f < out.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) fin |= out.V.row(out.F(f, c)) == m.V.row(nv);
  EXPECT_TRUE(fin);
}

}  // namespace
}  // namespace arg
