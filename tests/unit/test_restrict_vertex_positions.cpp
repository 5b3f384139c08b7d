// Restriction: a fine mesh's vertex positions carried to its collapsed copy's vertices.
#include <gtest/gtest.h>

#include <stdexcept>

#include "collapsed_torus.hpp"
#include "mesh/mesh_edges.hpp"
#include "mesh/restrict_vertex_positions.hpp"
#include "mesh/taubin_smoothing.hpp"

using namespace arg;
using test::collapsed_torus;

TEST(RestrictVertexPositions, EachCopyVertexIsTheMeanOfWhatItGathered) {
  const test::Collapsed c = collapsed_torus();
  ASSERT_LT(c.coarse.V.rows(), c.fine.V.rows() / 3);
  // A field that is not affine in the position, so a mean differs from a value at one point.
  Vertices moved = c.fine.V;
  for (Eigen::Index v = 0; v < moved.rows(); ++v) moved(v, 2) += double(v % 7);
  const Mesh out = restrict_vertex_positions(c.coarse, c.map, moved);
  ASSERT_EQ(out.V.rows(), c.coarse.V.rows());
  EXPECT_TRUE(out.F == c.coarse.F);
  Vertices sum = Vertices::Zero(c.coarse.V.rows(), 3);
  std::vector<int> count(std::size_t(c.coarse.V.rows()), 0);
  for (std::size_t v = 0; v < c.map.size(); ++v) {
    ASSERT_GE(c.map[v], 0);
    sum.row(c.map[v]) += moved.row(Eigen::Index(v));
    ++count[std::size_t(c.map[v])];
  }
  for (Eigen::Index k = 0; k < out.V.rows(); ++k) {
    ASSERT_GT(count[std::size_t(k)], 0);
    EXPECT_LT((out.V.row(k) - sum.row(k) / count[std::size_t(k)]).norm(), 1e-12) << k;
  }
}

TEST(RestrictVertexPositions, AShiftOfTheFineSurfaceShiftsTheCopyAsFar) {
  // A mean of positions moves with them; the copy's own positions would not.
  const test::Collapsed c = collapsed_torus();
  const Mesh before = restrict_vertex_positions(c.coarse, c.map, c.fine.V);
  Vertices shifted = c.fine.V;
  shifted.rowwise() += Eigen::RowVector3d(0.5, -1.0, 2.0);
  const Mesh after = restrict_vertex_positions(c.coarse, c.map, shifted);
  for (Eigen::Index k = 0; k < after.V.rows(); ++k)
    EXPECT_LT((after.V.row(k) - before.V.row(k) - Eigen::RowVector3d(0.5, -1.0, 2.0)).norm(), 1e-12)
        << k;
}

TEST(RestrictVertexPositions, OnlyTheVerticesNothingMapsToKeepTheirPlace) {
  // Half the map unset: the copy vertices still reached take the mean of their mapped fine
  // vertices, moved here by a shift; the others stay where the copy has them.
  const test::Collapsed c = collapsed_torus();
  std::vector<int> half = c.map;
  for (std::size_t v = 0; v < half.size(); ++v)
    if (half[v] % 2 == 1) half[v] = -1;
  Vertices shifted = c.fine.V;
  shifted.rowwise() += Eigen::RowVector3d(0, 0, 3.0);
  const Mesh out = restrict_vertex_positions(c.coarse, half, shifted);
  int moved = 0, kept = 0;
  for (Eigen::Index k = 0; k < out.V.rows(); ++k) {
    if (k % 2 == 1) {
      EXPECT_TRUE(out.V.row(k) == c.coarse.V.row(k)) << k;
      ++kept;
    } else {
      EXPECT_GT(out.V(k, 2) - c.coarse.V(k, 2), 2.5) << k;
      ++moved;
    }
  }
  EXPECT_GT(moved, 100);
  EXPECT_GT(kept, 100);
}

TEST(RestrictVertexPositions, TheCopyOfASmoothedSurfaceIsSmootherThanTheCopy) {
  // What the views take on a copy of a rough surface: noise (up to 5% of the radius) on the
  // fine torus, smoothed and restricted, leaves the copy's vertices nearer the true torus (tube
  // radius 0.6 about the circle of radius 2) than the copy of the noisy surface.
  const test::Collapsed c = collapsed_torus();
  Mesh noisy = c.fine;
  for (Eigen::Index v = 0; v < noisy.V.rows(); ++v)
    noisy.V.row(v) *= 1.0 + 0.05 * double((v * 7919) % 11 - 5) / 5.0;
  const Mesh noisy_copy = restrict_vertex_positions(c.coarse, c.map, noisy.V);
  const Mesh smooth = taubin_smoothing(noisy, mesh_edges(noisy.F), 80, 0.5, -0.53, {});
  const Mesh smooth_copy = restrict_vertex_positions(c.coarse, c.map, smooth.V);
  auto off_torus = [](const Vertices& V) {
    double sum = 0;
    for (Eigen::Index k = 0; k < V.rows(); ++k) {
      const double ring = std::hypot(V(k, 0), V(k, 1)) - 2.0;
      sum += std::fabs(std::hypot(ring, V(k, 2)) - 0.6);
    }
    return sum / double(V.rows());
  };
  EXPECT_LT(off_torus(smooth_copy.V), 0.5 * off_torus(noisy_copy.V));
}

TEST(RestrictVertexPositions, AMapOfTheWrongSizeOrPastTheCopyIsRefused) {
  const test::Collapsed c = collapsed_torus();
  std::vector<int> short_map(c.map.begin(), c.map.end() - 1);
  EXPECT_THROW(restrict_vertex_positions(c.coarse, short_map, c.fine.V), std::invalid_argument);
  std::vector<int> past = c.map;
  past[3] = int(c.coarse.V.rows());
  EXPECT_THROW(restrict_vertex_positions(c.coarse, past, c.fine.V), std::invalid_argument);
}
