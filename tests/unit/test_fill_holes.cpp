// Closing holes: closed, consistently oriented results, the volume of what the hole cut into.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "mesh/fill_holes.hpp"
#include "mesh/mesh_edges.hpp"
#include "pipeline/build_arg.hpp"
#include "test_exact_meshes.hpp"
#include "test_shapes.hpp"
#include "test_torn_meshes.hpp"

namespace arg {
namespace {

using test::signed_volume;

// Every edge used exactly once in each direction: closed and consistently oriented.
bool closed_and_oriented(const Mesh& m) {
  std::map<std::pair<int, int>, int> used;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++used[{m.F(f, k), m.F(f, (k + 1) % 3)}];
  for (const auto& [edge, count] : used)
    if (count != 1 || used.count({edge.second, edge.first}) != 1 ||
        used.at({edge.second, edge.first}) != 1)
      return false;
  return true;
}

Mesh without_faces(const Mesh& m, const std::vector<Eigen::Index>& drop) {
  Mesh out = m;
  Eigen::Index kept = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (std::find(drop.begin(), drop.end(), f) == drop.end()) {
      if (m.has_colour()) out.C.row(kept) = m.C.row(f);
      out.F.row(kept++) = m.F.row(f);
    }
  out.F.conservativeResize(kept, 3);
  if (m.has_colour()) out.C.conservativeResize(kept, 3);
  return out;
}

TEST(FillHoles, AClosedMeshIsLeftAsItIs) {
  const Mesh cube = test::cube(2);
  FillReport report;
  const Mesh out = fill_holes(cube, &report);
  EXPECT_EQ(report.loops, 0u);
  EXPECT_TRUE(out.V == cube.V);
  EXPECT_TRUE(out.F == cube.F);
}

TEST(FillHoles, ATriangularHoleGetsOneTriangleAndTheCubeItsVolume) {
  const Mesh cube = test::cube(1);  // 12 triangles, volume 8
  const Mesh open = without_faces(cube, {5});
  ASSERT_FALSE(closed_and_oriented(open));
  FillReport report;
  const Mesh out = fill_holes(open, &report);
  EXPECT_EQ(report.loops, 1u);
  EXPECT_EQ(report.added_faces, 1u);
  EXPECT_EQ(out.V.rows(), cube.V.rows()) << "no new vertex for three edges";
  EXPECT_TRUE(closed_and_oriented(out));
  EXPECT_NEAR(signed_volume(out), 8.0, 1e-12);
}

TEST(FillHoles, ALongerLoopGetsAFanAroundItsCentre) {
  // A whole face of a 3 x 3 cube removed: a square loop of 12 edges, a flat fan closes it.
  const Mesh cube = test::cube(3);
  std::vector<Eigen::Index> top;
  for (Eigen::Index f = 0; f < cube.F.rows(); ++f) {
    bool on_top = true;
    for (int k = 0; k < 3; ++k) on_top = on_top && cube.V(cube.F(f, k), 2) > 0.999;
    if (on_top) top.push_back(f);
  }
  ASSERT_EQ(top.size(), 18u);
  FillReport report;
  const Mesh out = fill_holes(without_faces(cube, top), &report);
  EXPECT_EQ(report.loops, 1u);
  EXPECT_EQ(report.added_faces, 12u);
  ASSERT_EQ(out.V.rows(), cube.V.rows() + 1);
  EXPECT_NEAR((out.V.row(out.V.rows() - 1) - Eigen::RowVector3d(0, 0, 1)).norm(), 0, 1e-12);
  EXPECT_TRUE(closed_and_oriented(out));
  EXPECT_NEAR(signed_volume(out), 8.0, 1e-12);
}

TEST(FillHoles, ALoopThroughAVertexTwiceIsLeftOpen) {
  // Two triangles of the 1 x 1 cube that meet at one corner only: their holes touch there.
  const Mesh cube = test::cube(1);
  std::vector<Eigen::Index> pair;
  for (Eigen::Index f = 0; f < cube.F.rows() && pair.empty(); ++f)
    for (Eigen::Index g = f + 1; g < cube.F.rows(); ++g) {
      int shared = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) shared += cube.F(f, i) == cube.F(g, j);
      if (shared == 1) {
        pair = {f, g};
        break;
      }
    }
  ASSERT_EQ(pair.size(), 2u);
  FillReport report;
  const Mesh out = fill_holes(without_faces(cube, pair), &report);
  EXPECT_EQ(report.loops, 0u);
  EXPECT_GE(report.skipped_loops, 1u);
  EXPECT_EQ(out.F.rows(), cube.F.rows() - 2);
}

TEST(FillHoles, NewFacesTakeTheMeanColourOfTheRim) {
  Mesh cube = test::cube(1);
  cube.C.resize(cube.F.rows(), 3);
  for (Eigen::Index f = 0; f < cube.F.rows(); ++f)
    cube.C.row(f) = Eigen::RowVector3f(float(f) / 12.0f, 0.5f, 1.0f);
  const Mesh open = without_faces(cube, {5});
  const Mesh out = fill_holes(open);
  ASSERT_TRUE(out.has_colour());
  EXPECT_TRUE(out.C.topRows(open.F.rows()) == open.C);
  EXPECT_FLOAT_EQ(out.C(out.F.rows() - 1, 1), 0.5f);
}

TEST(FillHoles, AnArgOfACapsuleWithAHoleIsNearlyTheClosedOnes) {
  const Mesh closed = test::capsule(3, 0.5, 120, 40);
  Mesh open = closed;
  Eigen::Index kept = 0;
  const Eigen::RowVector3d centre(0.5, 0, 1);
  for (Eigen::Index f = 0; f < closed.F.rows(); ++f) {
    const Eigen::RowVector3d c = (closed.V.row(closed.F(f, 0)) + closed.V.row(closed.F(f, 1)) +
                                  closed.V.row(closed.F(f, 2))) /
                                 3.0;
    if ((c - centre).norm() > 0.3) open.F.row(kept++) = closed.F.row(f);
  }
  open.F.conservativeResize(kept, 3);
  BuildOptions keep;
  keep.holes = HoleKind::Keep;
  const ArgGraph whole = build_arg(closed), filled = build_arg(open),
                 kept_open = build_arg(open, keep);
  EXPECT_EQ(filled.options.holes, HoleKind::Fill);
  EXPECT_TRUE(filled.summary.flags & kFlagOpen) << "the flag says the input was open";
  ASSERT_EQ(filled.spectrum.size(), whole.spectrum.size());
  // The filled capsule's spectrum is nearer the closed one's than the open capsule's.
  auto gap = [&](const ArgGraph& g) {
    double s = 0;
    for (std::size_t k = 0; k < g.spectrum.size(); ++k)
      s += std::fabs(std::log(g.spectrum[k] / whole.spectrum[k]));
    return s;
  };
  EXPECT_LT(gap(filled), gap(kept_open));
}

}  // namespace
}  // namespace arg
