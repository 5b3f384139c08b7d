// Cutting a node's triangles out as a mesh: a partition of the surface, compact, checked input.
#include <gtest/gtest.h>

#include <vector>

#include "common/errors.hpp"
#include "gen/generate_models.hpp"
#include "mesh/surface_area.hpp"
#include "pipeline/node_positions.hpp"
#include "pipeline/node_region.hpp"

using namespace arg;

namespace {

const NodePositions& human() {
  static const NodePositions p = node_positions(generate_model("human", 0, 32).mesh);
  return p;
}

}  // namespace

TEST(NodeRegion, TheNodesOfALevelPartitionTheTriangles) {
  const NodePositions& p = human();
  ASSERT_GE(p.levels.size(), 3u);
  for (int level = 0; level < int(p.levels.size()); ++level) {
    long faces = 0;
    double area = 0;
    for (int node = 0; node < int(p.levels[std::size_t(level)].area.size()); ++node) {
      long owned = 0;
      for (int f = 0; f < int(p.mesh.F.rows()); ++f) owned += face_node(p, level, f) == node;
      if (owned == 0) {
        EXPECT_THROW(node_region(p, level, node), InputError);
        continue;
      }
      const Mesh part = node_region(p, level, node);
      EXPECT_EQ(part.F.rows(), owned) << "level " << level << " node " << node;
      faces += part.F.rows();
      area += surface_area(part);
    }
    EXPECT_EQ(faces, p.mesh.F.rows()) << "level " << level;
    EXPECT_NEAR(area, surface_area(p.mesh), 1e-9 * surface_area(p.mesh));
  }
}

TEST(NodeRegion, KeepsOnlyTheVerticesItsTrianglesUse) {
  const NodePositions& p = human();
  const int level = 2;
  for (int node = 0; node < int(p.levels[level].area.size()); ++node) {
    std::vector<int> original;  // the source triangles, in order
    for (int f = 0; f < int(p.mesh.F.rows()); ++f)
      if (face_node(p, level, f) == node) original.push_back(f);
    if (original.empty()) continue;
    const Mesh part = node_region(p, level, node);
    std::vector<char> used(std::size_t(part.V.rows()), 0);
    for (long f = 0; f < part.F.rows(); ++f)
      for (int c = 0; c < 3; ++c) {
        const int v = part.F(f, c);
        ASSERT_GE(v, 0);
        ASSERT_LT(v, part.V.rows());
        used[std::size_t(v)] = 1;
        // The same corner, at the same place, as in the source triangle.
        EXPECT_EQ(part.V.row(v), p.mesh.V.row(p.mesh.F(original[std::size_t(f)], c)));
      }
    for (char u : used) EXPECT_TRUE(u);
  }
}

TEST(NodeRegion, ItsShareOfTheSurfaceIsTheNodesArea) {
  // A node's area share is measured on the triangles split at the mu interval bounds; the cut
  // gives each triangle whole to the node of its middle, so the two agree up to a band of
  // triangles along the cut.
  const NodePositions& p = human();
  const int level = 1;
  const double total = surface_area(p.mesh);
  const auto& areas = p.levels[level].area;
  double sum = 0;
  for (double a : areas) sum += a;
  int checked = 0;
  for (int node = 0; node < int(areas.size()); ++node) {
    if (areas[std::size_t(node)] < 0.05 * sum) continue;
    const double share = surface_area(node_region(p, level, node)) / total;
    EXPECT_NEAR(share, areas[std::size_t(node)] / sum, 0.03) << "node " << node;
    ++checked;
  }
  EXPECT_GE(checked, 2);
}

TEST(NodeRegion, ColoursFollowTheirTriangles) {
  NodePositions p = human();
  p.mesh.C.resize(p.mesh.F.rows(), 3);
  for (long f = 0; f < p.mesh.F.rows(); ++f) p.mesh.C.row(f) << float(f % 7), float(f), 0.5f;
  const Mesh part = node_region(p, 1, 0);
  ASSERT_TRUE(part.has_colour());
  long k = 0;
  for (int f = 0; f < int(p.mesh.F.rows()); ++f)
    if (face_node(p, 1, f) == 0) {
      EXPECT_EQ(part.C.row(k++), p.mesh.C.row(f));
    }
  EXPECT_EQ(k, part.F.rows());
}

TEST(NodeRegion, RefusesALevelOrNodeItDoesNotHave) {
  const NodePositions& p = human();
  EXPECT_THROW(node_region(p, -1, 0), InputError);
  EXPECT_THROW(node_region(p, int(p.levels.size()), 0), InputError);
  EXPECT_THROW(node_region(p, 0, int(p.levels[0].area.size())), InputError);
  EXPECT_THROW(node_region(p, 1, -1), InputError);
  EXPECT_EQ(face_node(p, 0, -1), -1);
  EXPECT_EQ(face_node(p, 0, int(p.mesh.F.rows())), -1);
  EXPECT_EQ(face_node(p, int(p.levels.size()), 0), -1);
}
