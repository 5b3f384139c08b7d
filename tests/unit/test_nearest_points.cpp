// The grid's nearest point equals brute force's, ties to the lowest index, also for queries far
// outside the points' box and for points on a plane or all in one place.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mesh/nearest_points.hpp"

namespace arg {
namespace {

int brute_force(const Vertices& points, const Eigen::Vector3d& q) {
  int best = -1;
  double best_d2 = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double d2 = (points.row(i).transpose() - q).squaredNorm();
    if (best < 0 || d2 < best_d2) best = int(i), best_d2 = d2;
  }
  return best;
}

Vertices random_points(int n, std::mt19937& rng, double flat = 1) {
  std::uniform_real_distribution<double> u(-1, 1);
  Vertices v(n, 3);
  for (int i = 0; i < n; ++i) v.row(i) << u(rng), 3 * u(rng), flat * u(rng);
  return v;
}

TEST(NearestPoints, AgreesWithBruteForceInsideAndFarOutside) {
  std::mt19937 rng(7);
  for (double flat : {1.0, 0.0}) {
    const Vertices points = random_points(2000, rng, flat);
    const NearestPoints index(points);
    std::uniform_real_distribution<double> u(-10, 10);
    for (int k = 0; k < 500; ++k) {
      const Eigen::Vector3d q = k % 2 ? Eigen::Vector3d(u(rng) / 10, u(rng) / 3, u(rng) / 10)
                                      : Eigen::Vector3d(u(rng), u(rng), u(rng));
      ASSERT_EQ(index.nearest(q), brute_force(points, q)) << "flat " << flat << " query " << k;
    }
  }
}

TEST(NearestPoints, TiesGoToTheLowestIndexAndNoPointsGiveMinusOne) {
  Vertices same(5, 3);
  same.setConstant(2.0);
  EXPECT_EQ(NearestPoints(same).nearest(Eigen::Vector3d(0, 0, 0)), 0);
  Vertices mirrored(2, 3);
  mirrored << 1, 0, 0, -1, 0, 0;
  EXPECT_EQ(NearestPoints(mirrored).nearest(Eigen::Vector3d(0, 5, 0)), 0);
  const Vertices none(0, 3);
  EXPECT_EQ(NearestPoints(none).nearest(Eigen::Vector3d(0, 0, 0)), -1);
}

}  // namespace
}  // namespace arg

namespace arg {
namespace {

TEST(NearestPoints, FewPointsOnAPlaneOrALineStayFewCellsAndNonFiniteQueriesFindNone) {
  Vertices corners(4, 3);
  corners << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  const NearestPoints square(corners);
  EXPECT_EQ(square.nearest(Eigen::Vector3d(0.5, 0.5, 0)), 0);
  EXPECT_EQ(square.nearest(Eigen::Vector3d(0.9, 0.8, 3)), 2);
  Vertices line(2, 3);
  line << 0, 0, 0, 0, 0, 1e6;
  EXPECT_EQ(NearestPoints(line).nearest(Eigen::Vector3d(1, 1, 6e5)), 1);
  EXPECT_EQ(square.nearest(Eigen::Vector3d(std::nan(""), 0, 0)), -1);
  EXPECT_EQ(square.nearest(Eigen::Vector3d(1e6, 0, 0)), 1);
  Vertices odd(3, 3);
  odd << 0, 0, 0, std::numeric_limits<double>::infinity(), 0, 0, 2, 0, 0;
  EXPECT_EQ(NearestPoints(odd).nearest(Eigen::Vector3d(1.5, 0, 0)), 2);
}

}  // namespace
}  // namespace arg
