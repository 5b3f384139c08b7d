// A mesh restricted to some faces: the kept faces and colours in order, vertices as numbered.
#include <gtest/gtest.h>

#include "mesh/face_subset.hpp"
#include "test_exact_meshes.hpp"

namespace arg {
namespace {

TEST(FaceSubset, KeepsTheChosenFacesTheirColoursAndEveryVertex) {
  Mesh cube = test::cube(1);
  cube.C.resize(cube.F.rows(), 3);
  for (Eigen::Index f = 0; f < cube.F.rows(); ++f)
    cube.C.row(f) = Eigen::RowVector3f(float(f), 0, 1);
  std::vector<char> keep(std::size_t(cube.F.rows()), 0);
  keep[2] = keep[7] = 1;
  const Mesh out = face_subset(cube, keep);
  EXPECT_TRUE(out.V == cube.V);
  ASSERT_EQ(out.F.rows(), 2);
  EXPECT_TRUE(out.F.row(0) == cube.F.row(2));
  EXPECT_TRUE(out.F.row(1) == cube.F.row(7));
  ASSERT_TRUE(out.has_colour());
  EXPECT_EQ(out.C(0, 0), 2.0f);
  EXPECT_EQ(out.C(1, 0), 7.0f);
}

TEST(FaceSubset, NoFacesKeptLeavesNoColour) {
  const Mesh cube = test::cube(1);
  const Mesh out = face_subset(cube, std::vector<char>(std::size_t(cube.F.rows()), 0));
  EXPECT_EQ(out.F.rows(), 0);
  EXPECT_FALSE(out.has_colour());
}

}  // namespace
}  // namespace arg
