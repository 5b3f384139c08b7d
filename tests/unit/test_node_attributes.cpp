// Node attributes and curvature measured on shapes whose volume, curvature and radii are known.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "features/curvature.hpp"
#include "features/histogram_bins.hpp"
#include "features/node_attributes.hpp"
#include "mesh/mesh_edges.hpp"
#include "mu/mu_function.hpp"
#include "reeb/reeb_levels.hpp"
#include "reeb/slice_intervals.hpp"
#include "test_exact_meshes.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

struct Attributed {
  std::vector<std::vector<ArgNode>> nodes;  // per level
  double volume = 0;
};

Attributed attributes(const Mesh& m, const std::vector<double>& mu, int levels) {
  const MeshEdges edges = mesh_edges(m.F);
  const SlicedSurface sliced = slice_intervals(m, mu, 1 << levels);
  const ReebGraph reeb = reeb_levels(sliced, edges, levels);
  Attributed out;
  out.nodes = node_attributes(m, sliced, reeb, triangle_curvature(m, edges), &out.volume);
  return out;
}

// mu = (p . axis) mapped onto [0, 1].
std::vector<double> along(const Mesh& m, const Eigen::Vector3d& axis) {
  std::vector<double> mu(std::size_t(m.V.rows()));
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) mu[std::size_t(v)] = m.V.row(v).dot(axis);
  normalise_min_max(mu);
  return mu;
}

template <std::size_t N>
double sum(const std::array<float, N>& h) {
  return std::accumulate(h.begin(), h.end(), 0.0);
}

// Integral over the surface of a per-triangle value.
double integral(const Mesh& m, const std::vector<double>& per_triangle) {
  double s = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::RowVector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    s += 0.5 * (b - a).cross(c - a).norm() * per_triangle[std::size_t(f)];
  }
  return s;
}

}  // namespace

TEST(NodeAttributes, ACubesVolumeIsExactAndEachSlabHoldsItsShare) {
  // Turned, so that no face is parallel to a coordinate plane; sliced along its own first
  // axis into 8 slabs of a quarter each: the end slabs carry a face more.
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Mesh cube = test::transformed(test::cube(5), turn, Eigen::Vector3d::Zero(), 1.0);
  const int levels = 3;
  const Attributed x = attributes(cube, along(cube, turn.col(0)), levels);
  EXPECT_NEAR(x.volume, 8.0, 1e-12);
  const double per_level = 1.0 / (levels + 1);
  const auto& finest = x.nodes[std::size_t(levels)];
  ASSERT_EQ(finest.size(), 8u);
  for (const ArgNode& n : finest) {
    EXPECT_NEAR(n.v, per_level / 8, 1e-6) << "interval " << n.interval;
    const bool end = n.interval == 0 || n.interval == 7;
    EXPECT_NEAR(n.a, per_level * ((end ? 4.0 : 0.0) + 8 * 0.25) / 24, 1e-6)
        << "interval " << n.interval;
  }
  // Sliced along a diagonal instead, slabs differ, but the caps between neighbours cancel:
  // every level still encloses the whole cube.
  const Attributed y = attributes(cube, along(cube, turn * Eigen::Vector3d(1, 1, 1)), levels);
  EXPECT_NEAR(y.volume, 8.0, 1e-12);
  for (const auto& level : y.nodes) {
    double v = 0;
    for (const ArgNode& n : level) {
      EXPECT_GT(n.v, 0.0f);
      v += n.v;
    }
    EXPECT_NEAR(v, per_level, 1e-6);
  }
}

TEST(NodeAttributes, ACubesCurvatureLiesOnItsEdgesAndCorners) {
  const Mesh cube = test::cube(4);
  const TriangleCurvature k = triangle_curvature(cube, mesh_edges(cube.F));
  // Discrete Gauss-Bonnet: the angle defects of a sphere-like surface add up to 4 pi, all
  // at the 8 corners. The mean curvature integrates to half the sum of edge length x dihedral
  // angle: 12 edges of length 2 at a right angle, 6 pi.
  EXPECT_NEAR(integral(cube, k.gaussian), 4 * M_PI, 1e-9);
  EXPECT_NEAR(integral(cube, k.mean), 6 * M_PI, 1e-9);
  // Triangles with no corner on an edge of the cube are flat.
  for (Eigen::Index f = 0; f < cube.F.rows(); ++f) {
    bool on_edge = false;
    for (int c = 0; c < 3; ++c) {
      int extreme = 0;
      for (int a = 0; a < 3; ++a) extreme += std::fabs(cube.V(cube.F(f, c), a)) == 1.0;
      on_edge |= extreme >= 2;
    }
    if (on_edge) continue;
    EXPECT_NEAR(k.mean[std::size_t(f)], 0.0, 1e-6);
    EXPECT_NEAR(k.gaussian[std::size_t(f)], 0.0, 1e-6);
  }
}

TEST(NodeAttributes, ASpheresCurvatureFillsTheBinOfOneOverItsRadius) {
  // An icosphere (outward, nearly equal triangles) of two radii, sliced along z. Its dihedral
  // angles are edge length / R, so mean curvature is 1/R and Gaussian 1/R^2 on every
  // triangle: measured within -0.01% .. +4.9% and +0.14% .. +5.1%.
  for (const double radius : {0.75, 0.3}) {
    const Mesh m = test::scaled(test::icosphere(3), radius);
    const TriangleCurvature k = triangle_curvature(m, mesh_edges(m.F));
    EXPECT_NEAR(integral(m, k.gaussian), 4 * M_PI, 1e-9);
    for (std::size_t f = 0; f < k.mean.size(); ++f) {
      EXPECT_GT(k.mean[f] * radius - 1, -0.001);
      EXPECT_LT(k.mean[f] * radius - 1, 0.06);
      EXPECT_GT(k.gaussian[f] * radius * radius - 1, 0.0);
      EXPECT_LT(k.gaussian[f] * radius * radius - 1, 0.06);
    }
    const int mean_bin = curvature_bin(1 / radius), gauss_bin = gaussian_bin(1 / radius / radius);
    EXPECT_EQ(mean_bin, radius > 0.5 ? 5 : 6);  // the two radii fall in different bins
    EXPECT_EQ(gauss_bin, mean_bin);
    const Attributed x = attributes(m, along(m, Eigen::Vector3d(0, 0, 1)), 5);
    for (const auto& level : x.nodes)
      for (const ArgNode& n : level) {
        EXPECT_NEAR(sum(n.curv_mean), n.a, 1e-6);
        EXPECT_NEAR(sum(n.curv_gauss), n.a, 1e-6);
        EXPECT_NEAR(n.curv_mean[std::size_t(mean_bin)], n.a, 1e-6);
        EXPECT_NEAR(n.curv_gauss[std::size_t(gauss_bin)], n.a, 1e-6);
      }
  }
}

TEST(NodeAttributes, ASpheresCordsAreRadiiOfOneLength) {
  for (const double radius : {0.75, 0.3}) {
    const Mesh m = test::scaled(test::icosphere(3), radius);
    const Attributed x = attributes(m, along(m, Eigen::Vector3d(0, 0, 1)), 5);
    // The whole sphere's barycentre is its centre, so its cords are radii, all in one bin.
    const ArgNode& whole = x.nodes[0].at(0);
    EXPECT_LT(whole.r, 1e-12);
    const int bin = cords_bin(radius);
    EXPECT_EQ(bin, radius > 0.5 ? 5 : 4);
    EXPECT_NEAR(whole.cords[std::size_t(bin)], whole.a, 1e-6);
    // The icosahedron is symmetric under a half turn about z, and so is every slab across z:
    // their barycentres lie on the axis, from which their cords run out to the surface.
    for (const auto& level : x.nodes)
      for (const ArgNode& n : level) {
        EXPECT_LT(n.r * std::sin(n.phi), 1e-9);
        EXPECT_NEAR(sum(n.cords), n.a, 1e-6);
      }
  }
}
