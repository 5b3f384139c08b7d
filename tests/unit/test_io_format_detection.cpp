// Tests that mesh formats are recognised from their content alone.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "io/read_mesh.hpp"
#include "test_io_support.hpp"

namespace arg {
namespace {

using test_io::Bytes;

TEST(IoFormatDetection, RecognisesEachFormatByItsContent) {
  EXPECT_EQ(detect_mesh_format("OFF\n3 1 0\n"), MeshFormat::Off);
  EXPECT_EQ(detect_mesh_format("# made by hand\n\nCOFF\n"), MeshFormat::Off);
  EXPECT_EQ(detect_mesh_format("NOFF 3 1 0\n"), MeshFormat::Off);
  EXPECT_EQ(detect_mesh_format("OFF BINARY\n"), MeshFormat::Off);
  EXPECT_EQ(detect_mesh_format("# obj\nv 0 0 0\n"), MeshFormat::Obj);
  EXPECT_EQ(detect_mesh_format("mtllib a.mtl\no thing\n"), MeshFormat::Obj);
  EXPECT_EQ(detect_mesh_format("ply\nformat ascii 1.0\n"), MeshFormat::Ply);
  EXPECT_EQ(detect_mesh_format("ply\r\nformat binary_big_endian 1.0\r\n"), MeshFormat::Ply);
  EXPECT_EQ(detect_mesh_format("solid cube\n facet normal 0 0 1\n"), MeshFormat::Stl);
  EXPECT_EQ(detect_mesh_format(std::string("glTF\x02\0\0\0", 8)), MeshFormat::Glb);
}

TEST(IoFormatDetection, BinaryStlIsRecognisedByItsSizeEvenWhenItStartsWithSolid) {
  Bytes stl;
  stl.text("solid but binary").pad_to(80, ' ').u32le(2);
  for (int i = 0; i < 100; ++i) stl.u8(0);
  ASSERT_EQ(stl.size(), 84u + 2 * 50u);
  EXPECT_EQ(detect_mesh_format(stl.str()), MeshFormat::Stl);
  // Its header may even look like another format.
  Bytes tricky;
  tricky.text("ply\nformat ascii 1.0\n").pad_to(80, ' ').u32le(0);
  EXPECT_EQ(detect_mesh_format(tricky.str()), MeshFormat::Stl);
}

TEST(IoFormatDetection, UnknownContentIsUnknownAndDoesNotThrow) {
  EXPECT_EQ(detect_mesh_format(""), MeshFormat::Unknown);
  EXPECT_EQ(detect_mesh_format("   \n\n"), MeshFormat::Unknown);
  EXPECT_EQ(detect_mesh_format("hello world"), MeshFormat::Unknown);
  EXPECT_EQ(detect_mesh_format(std::string("\0\1\2\3", 4)), MeshFormat::Unknown);
  EXPECT_STREQ(format_name(MeshFormat::Unknown), "unknown");
  EXPECT_STREQ(format_name(MeshFormat::Ply), "PLY");
  EXPECT_THROW(read_mesh("hello world"), InputError);
}

TEST(IoFormatDetection, TheCallerMayNameTheFormat) {
  ReadOptions options;
  options.format = MeshFormat::Off;
  const Mesh mesh = read_mesh(test_io::cube_off(), options);
  EXPECT_EQ(mesh.F.rows(), 12);
  options.format = MeshFormat::Ply;
  EXPECT_THROW(read_mesh(test_io::cube_off(), options), InputError);
}

TEST(IoFormatDetection, InputLargerThanTheLimitIsRefusedBeforeParsing) {
  ReadOptions options;
  options.limits.max_input_bytes = 10;
  EXPECT_THROW(read_mesh(test_io::cube_off(), options), LimitError);
}

}  // namespace
}  // namespace arg
