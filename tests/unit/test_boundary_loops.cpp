// Boundary loops: one per hole, walked as their faces run, and none on a closed mesh.
#include <gtest/gtest.h>

#include "mesh/boundary_loops.hpp"
#include "mesh/mesh_edges.hpp"
#include "test_exact_meshes.hpp"
#include "test_torn_meshes.hpp"

namespace arg {
namespace {

TEST(BoundaryLoops, AClosedMeshHasNone) {
  const Mesh sphere = test::icosphere(2);
  const BoundaryLoops found = boundary_loops(sphere, mesh_edges(sphere.F));
  EXPECT_TRUE(found.loops.empty());
  EXPECT_EQ(found.skipped, 0u);
}

TEST(BoundaryLoops, ARingCutOutLeavesTwoLoopsWalkedAsTheirFacesRun) {
  const Mesh cut = test::capsule_cut(0.5, 1.0);
  const MeshEdges edges = mesh_edges(cut.F);
  const BoundaryLoops found = boundary_loops(cut, edges);
  ASSERT_EQ(found.loops.size(), 2u);
  std::size_t boundary = 0;
  for (int e = 0; e < edges.count(); ++e) boundary += edges.faces(e) == 1;
  std::size_t walked = 0;
  for (const BoundaryLoop& loop : found.loops) {
    ASSERT_EQ(loop.vertices.size(), loop.faces.size());
    const std::size_t n = loop.vertices.size();
    walked += n;
    for (std::size_t i = 0; i < n; ++i) {
      // faces[i] holds the edge vertices[i] -> vertices[i + 1] in its own corner order.
      const int a = loop.vertices[i], b = loop.vertices[(i + 1) % n], f = loop.faces[i];
      bool runs = false;
      for (int c = 0; c < 3; ++c) runs |= cut.F(f, c) == a && cut.F(f, (c + 1) % 3) == b;
      EXPECT_TRUE(runs) << "edge " << i;
    }
  }
  EXPECT_EQ(walked, boundary);
}

TEST(BoundaryLoops, ALoopThroughAVertexTwiceIsSkipped) {
  // Two triangles sharing only vertex 0: the rim passes it twice.
  const Mesh bow = test::mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}},
                                 {{0, 1, 2}, {0, 3, 4}});
  const BoundaryLoops found = boundary_loops(bow, mesh_edges(bow.F));
  EXPECT_TRUE(found.loops.empty());
  EXPECT_GT(found.skipped, 0u);
}

}  // namespace
}  // namespace arg
