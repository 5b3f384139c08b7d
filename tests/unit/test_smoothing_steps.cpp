// The Taubin steps a build takes: none on a coarse mesh, 10 on a smooth fine one, 80 on noise.
#include <gtest/gtest.h>

#include <random>

#include "pipeline/build_arg.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

int steps_of(const Mesh& mesh) {
  BuildReport report;
  build_arg(mesh, BuildOptions{}, {}, &report);
  return report.smoothing_steps;
}

Mesh with_noise(Mesh m, double deviation) {
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, deviation);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) m.V.row(v) *= 1.0 + noise(random);
  return m;
}

}  // namespace

TEST(SmoothingSteps, ACoarseMeshKeepsItsEdges) {
  EXPECT_EQ(steps_of(test::sphere(8, 10)), 0);
}

TEST(SmoothingSteps, AFineSmoothSurfaceTakesTen) {
  EXPECT_EQ(steps_of(test::sphere(50, 80)), 10);   // 3,900 vertices, measured as they are
  EXPECT_EQ(steps_of(test::sphere(80, 100)), 10);  // 7,900: on a collapsed copy
}

// Noise along the normal of 0.3% of the diagonal, the size of perturb's noise of strength 3.
TEST(SmoothingSteps, NoiseOfAnEdgesSizeTakesEighty) {
  EXPECT_EQ(steps_of(with_noise(test::sphere(50, 80), 0.01)), 80);
  EXPECT_EQ(steps_of(with_noise(test::sphere(80, 100), 0.01)), 80);
}
