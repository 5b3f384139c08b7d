// Texture coordinates carried onto the surface an ARG is built on, and its colours kept.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/errors.hpp"
#include "gen/generate_models.hpp"
#include "pipeline/surface_texture.hpp"

using namespace arg;

namespace {

// Coordinates that are a linear function of the corner's place (s = x / 10, t = y / 10) plus
// 0.5 on t for odd triangles: a seam between every pair of neighbours.
std::vector<float> linear_uvs(const Mesh& mesh) {
  std::vector<float> uv;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      uv.push_back(float(mesh.V(mesh.F(f, k), 0) / 10));
      uv.push_back(float(mesh.V(mesh.F(f, k), 1) / 10 + (f % 2 ? 0.5 : 0.0)));
    }
  return uv;
}

// A surface point back in the input's frame (the pose undone).
Eigen::Vector3d unposed(const NodePositions& p, const Eigen::Vector3d& x) {
  return p.pose.rotation.transpose() * (x / p.pose.scale) + p.pose.centre;
}

Mesh human() {
  Mesh mesh = generate_model("human", 0, 32).mesh;
  mesh.C.resize(mesh.F.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) mesh.C.row(f) << float(f % 5) / 4, 0.5f, 0.25f;
  return mesh;
}

}  // namespace

TEST(SurfaceTexture, TheSurfaceIsNodePositionsOwnAndEachCornerKeepsItsCoordinates) {
  const Mesh input = human();
  SurfaceTexture texture;
  const NodePositions p = node_positions_with_texture(input, linear_uvs(input), {}, &texture);
  const NodePositions plain = node_positions(input);
  EXPECT_EQ(p.mesh.V, plain.mesh.V);
  EXPECT_EQ(p.mesh.F, plain.mesh.F);
  EXPECT_EQ(p.mu, plain.mu);
  ASSERT_EQ(p.levels.size(), plain.levels.size());
  for (std::size_t r = 0; r < p.levels.size(); ++r)
    EXPECT_EQ(p.levels[r].area, plain.levels[r].area);
  // A closed surface whose faces all come from the input's: the same colours, all textured.
  EXPECT_EQ(p.mesh.C, plain.mesh.C);
  const auto nf = std::size_t(p.mesh.F.rows());
  ASSERT_EQ(texture.uv.size(), 6 * nf);
  ASSERT_EQ(texture.textured.size(), nf);
  ASSERT_EQ(texture.origin.size(), nf);
  for (std::size_t f = 0; f < nf; ++f) {
    ASSERT_TRUE(texture.textured[f]) << "face " << f;
    // Its origin is the input triangle its colour comes from (the 3D view maps its texture).
    const int from = texture.origin[f];
    ASSERT_TRUE(from >= 0 && from < input.F.rows()) << "face " << f << ": " << from;
    EXPECT_EQ(p.mesh.C.row(long(f)), input.C.row(from));
    double seam[3];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d x = unposed(p, p.mesh.V.row(p.mesh.F(long(f), k)).transpose());
      EXPECT_NEAR(texture.uv[6 * f + 2 * std::size_t(k)], x[0] / 10, 1e-5);
      seam[k] = texture.uv[6 * f + 2 * std::size_t(k) + 1] - x[1] / 10;
      EXPECT_TRUE(std::fabs(seam[k]) < 1e-5 || std::fabs(seam[k] - 0.5) < 1e-5) << seam[k];
    }
    // The three corners of a face take their coordinates from the same input triangle.
    EXPECT_NEAR(seam[0], seam[1], 1e-5);
    EXPECT_NEAR(seam[0], seam[2], 1e-5);
  }
}

TEST(SurfaceTexture, AProxysFacesTakeTheirSourceTrianglesCoordinates) {
  const Mesh input = human();
  BuildOptions options;
  options.surface = SurfaceKind::Proxy;
  SurfaceTexture texture;
  const NodePositions p = node_positions_with_texture(input, linear_uvs(input), options, &texture);
  const NodePositions plain = node_positions(input, options);
  EXPECT_EQ(p.mesh.F, plain.mesh.F);
  EXPECT_EQ(p.mu, plain.mu);
  EXPECT_EQ(p.mesh.C, plain.mesh.C);  // the proxy copies its source faces' colours too
  std::size_t textured = 0;
  const double height = (input.V.col(1).maxCoeff() - input.V.col(1).minCoeff()) / 10;
  for (std::size_t f = 0; f < texture.textured.size(); ++f) {
    if (!texture.textured[f]) continue;
    ++textured;
    // Near where the corner lies: within the proxy's offset from the surface.
    const Eigen::Vector3d x = unposed(p, p.mesh.V.row(p.mesh.F(long(f), 0)).transpose());
    EXPECT_NEAR(texture.uv[6 * f], x[0] / 10, 0.1 * height);
  }
  EXPECT_EQ(textured, texture.textured.size());
}

TEST(SurfaceTexture, TrianglesWithoutCoordinatesGiveFacesWithout) {
  const Mesh input = human();
  std::vector<float> uv = linear_uvs(input);
  for (std::size_t i = 0; i < 6; ++i) uv[i] = std::nanf("");
  SurfaceTexture texture;
  node_positions_with_texture(input, uv, {}, &texture);
  std::size_t bare = 0;
  for (std::size_t f = 0; f < texture.textured.size(); ++f) {
    bare += !texture.textured[f];
    // The face without coordinates still has its origin: triangle 0.
    if (!texture.textured[f]) {
      EXPECT_EQ(texture.origin[f], 0);
    }
  }
  EXPECT_EQ(bare, 1u);
}

TEST(SurfaceTexture, CoordinatesNotSixPerTriangleAreRefused) {
  const Mesh input = human();
  std::vector<float> uv = linear_uvs(input);
  uv.pop_back();
  EXPECT_THROW(node_positions_with_texture(input, uv, {}, nullptr), InputError);
}
