// Cleaning's edge table: the one mesh_edges builds for the cleaned mesh, turned faces included.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

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

// Repeats of a face in any corner order are dropped and the first copy is the one kept, both
// where a vertex is the smallest corner of a few faces and at the centre of a fan of 64 faces
// (its faces sorted rather than searched pairwise).
TEST(CleanMeshDuplicates, KeepTheFirstCopyOnFansLargeAndSmall) {
  Mesh m;
  const int spokes = 64;
  m.V.resize(spokes + 1, 3);
  m.V.row(0) << 0, 0, 0;  // the centre, smallest corner of every face
  for (int k = 0; k < spokes; ++k)
    m.V.row(k + 1) << std::cos(2 * M_PI * k / spokes), std::sin(2 * M_PI * k / spokes), 0;
  for (int small : {0, 1}) {
    Mesh fan = m;
    std::vector<std::array<int, 3>> faces;
    // Without the centre (small = 1) the faces form a strip of the ring's neighbours: vertex k
    // is then the smallest corner of one or two faces.
    for (int k = 0; k < spokes - 1; ++k)
      faces.push_back(small ? std::array<int, 3>{k + 1, k + 2, (k + 2) % spokes + 1}
                            : std::array<int, 3>{0, k + 1, k + 2});
    const std::size_t unique = faces.size();
    // Repeats, each after its original, corners rotated or reversed.
    const std::array<int, 3> a = faces[5], b = faces[40];
    faces.push_back({a[1], a[2], a[0]});
    faces.push_back({b[2], b[1], b[0]});
    faces.push_back({a[2], a[0], a[1]});
    fan.F.resize(Eigen::Index(faces.size()), 3);
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (int c = 0; c < 3; ++c) fan.F(Eigen::Index(f), c) = faces[f][std::size_t(c)];
    CleanReport report;
    const Mesh clean = clean_mesh(fan, &report);
    EXPECT_EQ(report.dropped_duplicate, 3u) << "small " << small;
    ASSERT_EQ(clean.F.rows(), Eigen::Index(unique)) << "small " << small;
    EXPECT_EQ(report.dropped_degenerate, 0u);
  }
}
