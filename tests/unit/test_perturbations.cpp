// The robustness benchmark's transformations: deterministic, and each does what it says.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "common/errors.hpp"
#include "eval/perturbations.hpp"
#include "io/write_mesh.hpp"
#include "mesh/clean_mesh.hpp"
#include "mesh/connected_components.hpp"
#include "mesh/surface_area.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

double area(const Mesh& m) {
  return surface_area(m);
}

const Mesh& model() {
  static const Mesh m = test::capsule(2, 0.6, 60, 32);
  return m;
}

TEST(Perturbations, TheSameSeedGivesTheSameBytesAndAnotherSeedOthers) {
  for (Perturbation kind : all_perturbations())
    for (int s : {1, 3, 5}) {
      const std::string a = write_ply_binary(perturb(model(), kind, s, 7));
      EXPECT_EQ(a, write_ply_binary(perturb(model(), kind, s, 7))) << perturbation_name(kind);
      if (kind != Perturbation::Scale && kind != Perturbation::Decimate) {
        EXPECT_NE(a, write_ply_binary(perturb(model(), kind, s, 8))) << perturbation_name(kind);
      }
    }
}

TEST(Perturbations, HolesAndPartialRemovalOpenTheSurface) {
  for (Perturbation kind :
       {Perturbation::SmallHoles, Perturbation::LargeHoles, Perturbation::Partial}) {
    CleanReport report;
    const Mesh out = clean_mesh(perturb(model(), kind, 3, 1), &report);
    EXPECT_GT(report.boundary_edges, 0u) << perturbation_name(kind);
    EXPECT_LT(area(out), area(model())) << perturbation_name(kind);
  }
  // Partial removal takes 5 s % of the area.
  const double left = area(perturb(model(), Perturbation::Partial, 4, 1)) / area(model());
  EXPECT_NEAR(left, 0.8, 0.02);
}

TEST(Perturbations, SplittingMakesSeparateComponents) {
  std::vector<int> component;
  const Mesh out = perturb(model(), Perturbation::Split, 3, 1);
  EXPECT_GE(vertex_components(out, component), 3);
  EXPECT_NEAR(area(out), area(model()), 1e-9 * area(model()));  // nothing removed
}

TEST(Perturbations, DecimationAndRemeshingKeepTheirVertexBudgets) {
  const double n = double(model().V.rows());
  for (int s = 1; s <= 5; ++s) {
    const double kept = double(perturb(model(), Perturbation::Decimate, s, 1).V.rows()) / n;
    EXPECT_LE(kept, 0.5 - 0.075 * (s - 1) + 1e-9);
    EXPECT_GT(kept, 0.5 * (0.5 - 0.075 * (s - 1)));
    const double remeshed = double(perturb(model(), Perturbation::Remesh, s, 1).V.rows()) / n;
    EXPECT_LE(remeshed, 0.75 + 0.25 * s + 1e-9);
    EXPECT_GT(remeshed, 0.5 * (0.75 + 0.25 * s));
  }
  // The surface stays about where it was.
  EXPECT_NEAR(area(perturb(model(), Perturbation::Remesh, 3, 1)), area(model()),
              0.1 * area(model()));
}

TEST(Perturbations, NoiseAndScaleMoveVerticesByTheRightAmount) {
  const Mesh noisy = perturb(model(), Perturbation::Noise, 2, 1);
  ASSERT_EQ(noisy.V.rows(), model().V.rows());
  const double d = (model().V.colwise().maxCoeff() - model().V.colwise().minCoeff()).norm();
  const double rms = std::sqrt((noisy.V - model().V).squaredNorm() / double(3 * noisy.V.rows()));
  EXPECT_NEAR(rms, 0.002 * d, 0.0004 * d);
  const Mesh big = perturb(model(), Perturbation::Scale, 3, 1);
  EXPECT_TRUE(big.V.isApprox(8.0 * model().V));
  const Mesh shot = perturb(model(), Perturbation::ShotNoise, 5, 1);
  int moved = 0;
  for (Eigen::Index v = 0; v < shot.V.rows(); ++v) moved += shot.V.row(v) != model().V.row(v);
  EXPECT_GE(moved, 1);
  EXPECT_LE(moved, int(0.01 * double(shot.V.rows())) + 1);
}

std::size_t distinct_positions(const Mesh& m) {
  std::set<std::array<double, 3>> seen;
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) seen.insert({m.V(v, 0), m.V(v, 1), m.V(v, 2)});
  return seen.size();
}

TEST(Perturbations, NoiseMovesASoupsCoincidentCornersTogether) {
  const Mesh soup = test::unwelded(model());
  ASSERT_EQ(distinct_positions(soup), std::size_t(model().V.rows()));
  for (Perturbation kind : {Perturbation::Noise, Perturbation::ShotNoise}) {
    const Mesh noisy = perturb(soup, kind, 5, 1);
    EXPECT_EQ(distinct_positions(noisy), std::size_t(model().V.rows())) << perturbation_name(kind);
    EXPECT_GT((noisy.V - soup.V).norm(), 0) << perturbation_name(kind);
  }
}

TEST(Perturbations, DecimationKeepsTheShapeOfACoarseModelAndCountsASoupsPointsOnce) {
  const Mesh coarse = test::capsule(2, 0.6, 14, 10);
  for (int s : {1, 3, 5}) {
    const Mesh out = perturb(coarse, Perturbation::Decimate, s, 1);
    EXPECT_NEAR(area(out), area(coarse), 0.15 * area(coarse)) << s;
  }
  const Mesh soup = test::unwelded(model());
  const Mesh out = perturb(soup, Perturbation::Decimate, 3, 1);
  EXPECT_LE(double(out.V.rows()), 0.35 * double(model().V.rows()) + 1);
  EXPECT_NEAR(area(out), area(model()), 0.05 * area(model()));
}

TEST(Perturbations, ASmallHoleDoesNotTakeAFaceMuchLargerThanItself) {
  // A square of two triangles beside a fine capsule: a hole lands on the square as often as
  // its area says, but removes a triangle only if it falls near that triangle's centre.
  Mesh m = model();
  const Eigen::Index nv = m.V.rows(), nf = m.F.rows();
  m.V.conservativeResize(nv + 4, 3);
  m.V.bottomRows(4) << 3, -2, -2, 3, 2, -2, 3, 2, 2, 3, -2, 2;
  m.F.conservativeResize(nf + 2, 3);
  m.F.bottomRows(2) << int(nv), int(nv + 1), int(nv + 2), int(nv), int(nv + 2), int(nv + 3);
  int square_lost = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Mesh out = perturb(m, Perturbation::SmallHoles, 3, seed);
    square_lost += area(out) < area(m) - 7.9;  // a triangle of the square is 8
  }
  EXPECT_EQ(square_lost, 0);
}

TEST(Perturbations, AHoleOnACoarseFaceRemovesAboutItsOwnArea) {
  // A flat square of two triangles: one large hole (radius 0.06 D) takes at most its disc.
  const Mesh square = test::unit_square();
  const double r = 0.06 * std::sqrt(2.0), disc = M_PI * r * r;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const double removed = 1.0 - area(perturb(square, Perturbation::LargeHoles, 1, seed));
    EXPECT_GT(removed, 0.2 * disc) << seed;  // a quarter disc at the least, in a corner
    EXPECT_LT(removed, 1.15 * disc) << seed;
  }
}

TEST(Perturbations, NamesRoundTripAndBadStrengthsAreRefused) {
  for (Perturbation kind : all_perturbations())
    EXPECT_EQ(parse_perturbation(perturbation_name(kind)), kind);
  EXPECT_FALSE(parse_perturbation("melt").has_value());
  EXPECT_THROW(perturb(model(), Perturbation::Noise, 0, 1), InputError);
  EXPECT_THROW(perturb(model(), Perturbation::Noise, 6, 1), InputError);
}

}  // namespace
}  // namespace arg

namespace arg {

// A soup of loose triangles beside a sphere: the triangles have no edge to collapse that
// would keep them, so half the vertices is out of reach; decimation goes as far as it can.
TEST(Perturbations, ASoupThatCannotReachTheBudgetIsDecimatedAsFarAsCollapsesGo) {
  Mesh soup = test::sphere(12, 16);
  const Eigen::Index sphere_vertices = soup.V.rows(), sphere_faces = soup.F.rows();
  const int loose = 200;
  soup.V.conservativeResize(sphere_vertices + 3 * loose, 3);
  soup.F.conservativeResize(sphere_faces + loose, 3);
  for (int t = 0; t < loose; ++t) {
    const Eigen::Index v = sphere_vertices + 3 * t;
    const Eigen::RowVector3d at(3.0 + 0.1 * t, 0, 0);
    soup.V.row(v) = at;
    soup.V.row(v + 1) = at + Eigen::RowVector3d(0.05, 0, 0);
    soup.V.row(v + 2) = at + Eigen::RowVector3d(0, 0.05, 0);
    soup.F.row(sphere_faces + t) = Eigen::RowVector3i(int(v), int(v + 1), int(v + 2));
  }
  ASSERT_GT(3 * loose, soup.V.rows() / 2);  // the budget is out of reach
  const Mesh out = perturb(soup, Perturbation::Decimate, 1, 1);
  EXPECT_GT(out.F.rows(), 0);
  EXPECT_LT(out.V.rows(), soup.V.rows());
  EXPECT_GT(out.V.rows(), soup.V.rows() / 2);
}

}  // namespace arg
