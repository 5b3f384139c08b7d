// Normal offsets: small on a smooth surface, about noise over edge length on a noisy one.
#include <gtest/gtest.h>

#include <random>

#include "mesh/mesh_edges.hpp"
#include "mesh/surface_roughness.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

double mean_of(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return sum / double(values.size());
}

}  // namespace

TEST(SurfaceRoughness, ASmoothSphereStandsNearItsNeighboursMeans) {
  const Mesh sphere = test::sphere(40, 60);
  const std::vector<double> r = normal_offsets(sphere, mesh_edges(sphere.F));
  ASSERT_EQ(r.size(), std::size_t(sphere.V.rows()));
  // About h / (4 R) with edges of about a twentieth of the radius, the poles' fans aside.
  EXPECT_LT(mean_of(r), 0.05);
}

TEST(SurfaceRoughness, NoiseAlongTheNormalShowsAsItsSizeOverTheEdges) {
  Mesh noisy = test::sphere(40, 60);
  const std::vector<double> smooth = normal_offsets(noisy, mesh_edges(noisy.F));
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 0.02);  // about a fifth of an edge
  for (Eigen::Index v = 0; v < noisy.V.rows(); ++v) noisy.V.row(v) *= 1.0 + noise(random);
  const std::vector<double> rough = normal_offsets(noisy, mesh_edges(noisy.F));
  // The mean of |N(0, s^2 (1 + 1/6))| over edges of about 0.09: about 0.19.
  EXPECT_GT(mean_of(rough), 0.15);
  EXPECT_GT(mean_of(rough), 3 * mean_of(smooth));
}

TEST(SurfaceRoughness, AVertexOnNoEdgeHasNoOffset) {
  Mesh m = test::sphere(10, 12);
  m.V.conservativeResize(m.V.rows() + 1, 3);
  m.V.row(m.V.rows() - 1) = Eigen::RowVector3d(5, 5, 5);
  const std::vector<double> r = normal_offsets(m, mesh_edges(m.F));
  EXPECT_EQ(r.back(), 0.0);
}
