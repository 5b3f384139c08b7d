// The vessel profile: a surface of revolution's radius recovered along its axis, an upturned
// copy at distance ~0, and a box with three different sides scored as far from round.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "eval/baseline_descriptors.hpp"
#include "features/vessel_profile.hpp"
#include "test_exact_meshes.hpp"
#include "test_shapes.hpp"

namespace arg {
namespace {

// The vase's radius at height z in [-1.2, 1.2]: a belly, a neck and a lip.
double vase_radius(double z) {
  return 0.45 + 0.2 * std::sin(1.6 * z + 0.5) + 0.05 * z;
}

// An open surface of revolution about z (no bottom, no lid): 241 rings of 96 vertices.
Mesh open_vase() {
  const int rows = 241, cols = 96;
  std::vector<Eigen::RowVector3d> V;
  std::vector<Eigen::RowVector3i> F;
  for (int i = 0; i < rows; ++i) {
    const double z = -1.2 + 2.4 * i / (rows - 1), r = vase_radius(z);
    for (int j = 0; j < cols; ++j) {
      const double p = 2 * M_PI * j / cols;
      V.emplace_back(r * std::cos(p), r * std::sin(p), z);
    }
  }
  for (int i = 0; i + 1 < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const int a = i * cols + j, b = i * cols + (j + 1) % cols;
      F.emplace_back(a, b, b + cols);
      F.emplace_back(a, b + cols, a + cols);
    }
  return test::mesh_of(V, F);
}

Eigen::Matrix3d turn(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

TEST(VesselProfile, ASurfaceOfRevolutionsRadiusIsRecoveredBinByBin) {
  // Without tails the bins span the vase's whole height: 24 bins of 0.1.
  ProfileOptions whole;
  whole.tail = 0;
  const VesselProfile p = profile_about_axis(open_vase(), 2, whole);
  ASSERT_EQ(p.radius.size(), 24u);
  EXPECT_EQ(p.axis, 2);
  EXPECT_GT(p.symmetry, 0.97);
  EXPECT_NEAR(p.low, -1.2, 0.005);
  EXPECT_NEAR(p.high, 1.2, 0.005);
  double area = 0;
  for (std::size_t b = 0; b < 24; ++b) {
    area += p.area[b];
    const double centre = p.low + (p.high - p.low) * (double(b) + 0.5) / 24;
    EXPECT_NEAR(p.radius[b], vase_radius(centre), 0.01) << b;
    // One wall: the radius within a bin spreads only as much as the wall slopes across it.
    EXPECT_LT(p.spread[b], 0.02) << b;
  }
  EXPECT_NEAR(area, 1.0, 1e-9);
  // With the default tails, 1% of the surface lies beyond each end bin and joins it.
  const VesselProfile tailed = profile_about_axis(open_vase(), 2);
  EXPECT_GT(tailed.low, -1.2);
  EXPECT_LT(tailed.low, -1.1);
  EXPECT_LT(tailed.high, 1.2);
  EXPECT_GT(tailed.high, 1.1);
}

TEST(VesselProfile, TheAxisOfSymmetryIsFoundAfterPosing) {
  const Mesh vase = test::transformed(open_vase(), turn(0.7, {1, 2, 0.5}), {3, -2, 1}, 1.7);
  const VesselProfile p = vessel_profile(posed_for_descriptors(vase));
  EXPECT_GT(p.symmetry, 0.97);
  // The other two axes cut the vase across: far from round about either.
  const Mesh posed = posed_for_descriptors(vase);
  for (int axis = 0; axis < 3; ++axis)
    if (axis != p.axis) {
      EXPECT_LT(profile_about_axis(posed, axis).symmetry, 0.8) << axis;
    }
}

TEST(VesselProfile, AnUpturnedCopyIsTheSameVaseAndAnotherShapeIsFar) {
  const Mesh vase = open_vase();
  const Mesh upturned = test::transformed(vase, turn(M_PI, {1, 0, 0}), {0.5, 0, 2}, 0.6);
  const std::vector<float> a = profile_vector(vessel_profile(posed_for_descriptors(vase)));
  const std::vector<float> b = profile_vector(vessel_profile(posed_for_descriptors(upturned)));
  ASSERT_EQ(a.size(), 2u + 3 * 24);
  const double near = profile_distance(a, b);
  const double far =
      profile_distance(a, profile_vector(vessel_profile(posed_for_descriptors(test::capsule()))));
  EXPECT_LT(near, 0.1);
  EXPECT_GT(far, 10 * near);
  // The distance reads the bins either way up: a profile reversed by hand is at exactly 0,
  // though the vase is not the same either way up.
  std::vector<float> reversed = a;
  for (std::size_t part = 0; part < 3; ++part)
    std::reverse(reversed.begin() + long(2 + part * 24),
                 reversed.begin() + long(2 + part * 24 + 24));
  EXPECT_EQ(profile_distance(a, reversed), 0.0);
  EXPECT_GT(l1_distance(a, reversed), 1.0);
  EXPECT_EQ(profile_distance(a, a), 0.0);
}

TEST(VesselProfile, ABoxWithThreeDifferentSidesIsFarFromRound) {
  Mesh box = test::cube(8);
  for (Eigen::Index i = 0; i < box.V.rows(); ++i)
    box.V.row(i).array() *= Eigen::Array3d(0.5, 1, 2).transpose();
  const VesselProfile p = vessel_profile(posed_for_descriptors(box));
  EXPECT_LT(p.symmetry, 0.85);
  // A square section is rounder (about .89), a sphere rounder still (.99).
  Mesh square = test::cube(8);
  for (Eigen::Index i = 0; i < square.V.rows(); ++i) square.V(i, 2) *= 2;
  const double square_symmetry = vessel_profile(posed_for_descriptors(square)).symmetry;
  EXPECT_GT(square_symmetry, p.symmetry + 0.05);
  EXPECT_GT(vessel_profile(posed_for_descriptors(test::sphere())).symmetry, square_symmetry);
}

TEST(VesselProfile, AMeshWithoutAreaOrAMalformedVectorGivesNoNumbersOutOfRange) {
  const VesselProfile empty = vessel_profile(Mesh{});
  EXPECT_EQ(empty.symmetry, 0.0);
  EXPECT_EQ(empty.area.size(), 24u);
  const std::vector<float> a = profile_vector(vessel_profile(test::sphere()));
  // Sizes that do not match compare as far as both vectors reach, never past their ends.
  EXPECT_GT(profile_distance(a, {}), 1.0);
  EXPECT_GT(profile_distance(a, {1, 2}), profile_distance(a, {}));
}

}  // namespace
}  // namespace arg
