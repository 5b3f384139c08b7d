// Cleaning's edge table: the one mesh_edges builds for the cleaned mesh, turned faces included.
#include <gtest/gtest.h>

#include <initializer_list>
#include <utility>

#include "mesh/clean_mesh.hpp"
#include "mesh/mesh_edges.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

void expect_same_edges(const MeshEdges& a, const MeshEdges& b) {
  EXPECT_EQ(a.v0, b.v0);
  EXPECT_EQ(a.v1, b.v1);
  EXPECT_EQ(a.face_begin, b.face_begin);
  EXPECT_EQ(a.face_of, b.face_of);
  EXPECT_EQ(a.corner_of, b.corner_of);
}

}  // namespace

// Every third face turned over (orientation repair) and a whole mesh inside out (the volume
// turn): the corners of turned faces are renumbered, the rest of the table is as built.
TEST(CleanMeshEdges, AreTheCleanedMeshsOwnWhereverFacesTurned) {
  Mesh scrambled = test::torus(2, 0.6, 40, 16);
  for (Eigen::Index f = 0; f < scrambled.F.rows(); f += 3)
    std::swap(scrambled.F(f, 1), scrambled.F(f, 2));
  const Mesh sphere = test::sphere(20, 30);
  Mesh reversed = sphere;  // one of the two is inside out
  for (Eigen::Index f = 0; f < reversed.F.rows(); ++f)
    std::swap(reversed.F(f, 0), reversed.F(f, 2));
  std::size_t turned = 0;
  for (const Mesh* m : std::initializer_list<const Mesh*>{&scrambled, &sphere, &reversed}) {
    CleanReport report;
    MeshEdges edges;
    const Mesh clean = clean_mesh(*m, &report, {}, &edges);
    turned += report.flipped_faces;
    expect_same_edges(edges, mesh_edges(clean.F));
  }
  EXPECT_GT(turned, std::size_t(sphere.F.rows()));
}

// Welded copies and dropped faces renumber vertices and faces: the table follows the output.
TEST(CleanMeshEdges, FollowWeldsAndDroppedFaces) {
  Mesh m = test::sphere(12, 16);
  const Eigen::Index nv = m.V.rows(), nf = m.F.rows();
  m.V.conservativeResize(nv + 3, 3);
  m.V.bottomRows(3) = m.V.topRows(3);  // copies of the first three vertices, welded back
  m.F.conservativeResize(nf + 2, 3);
  m.F.row(nf) << int(nv), m.F(0, 1), m.F(0, 2);  // a duplicate through a welded copy
  m.F.row(nf + 1) << 0, 0, 1;                    // a degenerate face
  CleanReport report;
  MeshEdges edges;
  const Mesh clean = clean_mesh(m, &report, {}, &edges);
  EXPECT_EQ(report.dropped_duplicate + report.dropped_degenerate, 2u);
  expect_same_edges(edges, mesh_edges(clean.F));
}
