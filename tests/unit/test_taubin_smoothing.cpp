// Taubin smoothing: noise of an edge's size fades, the shape keeps its size and connectivity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mesh/mesh_edges.hpp"
#include "mesh/taubin_smoothing.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

struct Radii {
  double mean = 0, deviation = 0;
};

Radii radii(const Mesh& m) {
  Radii r;
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) r.mean += m.V.row(v).norm();
  r.mean /= double(m.V.rows());
  for (Eigen::Index v = 0; v < m.V.rows(); ++v)
    r.deviation += std::pow(m.V.row(v).norm() - r.mean, 2);
  r.deviation = std::sqrt(r.deviation / double(m.V.rows()));
  return r;
}

// A unit sphere whose vertices moved along their radius by noise of a fifth of an edge.
Mesh noisy_sphere() {
  Mesh m = test::sphere(40, 60);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) m.V.row(v) *= 1.0 + noise(random);
  return m;
}

}  // namespace

TEST(TaubinSmoothing, NoiseOfAnEdgesSizeFadesWithoutShrinkingTheShape) {
  const Mesh noisy = noisy_sphere();
  const Mesh smooth = taubin_smoothing(noisy, mesh_edges(noisy.F), 10);
  const Radii before = radii(noisy), after = radii(smooth);
  EXPECT_NEAR(before.deviation, 0.02, 0.003);
  // What is left is mostly the grid's own unevenness near the poles, not the noise.
  EXPECT_LT(after.deviation, before.deviation / 2);
  // Plain Laplacian smoothing (mu = 0) shrinks a sphere by about lambda per step in its
  // highest frequencies and visibly overall; Taubin's pass keeps the radius.
  EXPECT_NEAR(after.mean, before.mean, 0.01);
  const Mesh laplacian = taubin_smoothing(noisy, mesh_edges(noisy.F), 10, 0.5, 0.5);
  EXPECT_LT(radii(laplacian).mean, before.mean - 0.01);
}

TEST(TaubinSmoothing, KeepsTrianglesColoursAndVertexCount) {
  Mesh noisy = noisy_sphere();
  noisy.C = FaceColours::Constant(noisy.F.rows(), 3, 0.25f);
  const Mesh smooth = taubin_smoothing(noisy, mesh_edges(noisy.F), 3);
  EXPECT_EQ(smooth.V.rows(), noisy.V.rows());
  EXPECT_TRUE(smooth.F == noisy.F);
  EXPECT_TRUE(smooth.C == noisy.C);
}

TEST(TaubinSmoothing, ZeroIterationsAndIsolatedVerticesLeaveTheMeshAsItIs) {
  Mesh m = noisy_sphere();
  const Mesh same = taubin_smoothing(m, mesh_edges(m.F), 0);
  EXPECT_TRUE(same.V == m.V);
  // A vertex no triangle uses has no neighbours to average: it stays where it was.
  m.V.conservativeResize(m.V.rows() + 1, 3);
  m.V.row(m.V.rows() - 1) = Eigen::RowVector3d(5, 5, 5);
  const Mesh smooth = taubin_smoothing(m, mesh_edges(m.F), 4);
  EXPECT_EQ(smooth.V.row(m.V.rows() - 1), Eigen::RowVector3d(5, 5, 5));
}

// The smoothing adds each vertex's neighbours in slots of a fixed width with unused slots at
// the origin; builds stay byte-identical only if that is bit for bit the plain loop below, on
// ordinary vertices and on the sphere's poles, whose 60 neighbours overflow the slots.
TEST(TaubinSmoothing, EqualsThePlainNeighbourMeanBitForBit) {
  const Mesh noisy = noisy_sphere();
  const MeshEdges edges = mesh_edges(noisy.F);
  std::vector<std::vector<int>> around(std::size_t(noisy.V.rows()));
  for (int e = 0; e < edges.count(); ++e) around[std::size_t(edges.v1[e])].push_back(edges.v0[e]);
  for (int e = 0; e < edges.count(); ++e) around[std::size_t(edges.v0[e])].push_back(edges.v1[e]);
  ASSERT_EQ(around.front().size(), 60u);  // a pole
  Vertices at = noisy.V;
  for (int it = 0; it < 2 * 5; ++it) {
    const double step = it % 2 == 0 ? 0.5 : -0.53;
    Vertices next = at;
    for (Eigen::Index v = 0; v < at.rows(); ++v) {
      double sum[3] = {0, 0, 0};
      for (int u : around[std::size_t(v)])
        for (int c = 0; c < 3; ++c) sum[c] += at(u, c);
      const double d = double(around[std::size_t(v)].size());
      for (int c = 0; c < 3; ++c) next(v, c) = at(v, c) + step * (sum[c] / d - at(v, c));
    }
    at = next;
  }
  const Mesh smooth = taubin_smoothing(noisy, edges, 5);
  for (Eigen::Index v = 0; v < at.rows(); ++v)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(smooth.V(v, c), at(v, c)) << "vertex " << v;
}
