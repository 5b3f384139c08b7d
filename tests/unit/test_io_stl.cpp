// Tests of reading STL (our parser): ASCII, binary, binary headers saying "solid", welding.
#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <sstream>

#include "common/errors.hpp"
#include "input_error.hpp"
#include "io/read_mesh.hpp"
#include "test_io_support.hpp"

namespace arg {
namespace {

using test_io::Bytes;

std::string cube_stl_ascii(const std::string& name = "cube") {
  std::ostringstream s;
  s << "solid " << name << "\n";
  const auto& v = test_io::cube_vertices();
  for (const auto& t : test_io::cube_triangles()) {
    s << "  facet normal 0 0 0\n    outer loop\n";
    for (int k : t)
      s << "      vertex " << v[std::size_t(k)][0] << ' ' << v[std::size_t(k)][1] << ' '
        << v[std::size_t(k)][2] << "\n";
    s << "    endloop\n  endfacet\n";
  }
  s << "endsolid " << name << "\n";
  return s.str();
}

std::string cube_stl_binary(const std::string& header) {
  Bytes b;
  b.text(header).pad_to(80, ' ');
  const auto triangles = test_io::cube_triangles();
  b.u32le(std::uint32_t(triangles.size()));
  const auto& v = test_io::cube_vertices();
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) b.f32le(0);
    for (int k : t) {
      for (double c : v[std::size_t(k)]) b.f32le(float(c));
    }
    b.u16le(0);
  }
  return b.str();
}

std::string error_of(const std::string& bytes) {
  return input_error_of([&] { read_mesh(bytes); });
}

TEST(ReadStl, AsciiAndBinaryReadTheOffCubeWithWeldedCorners) {
  const Mesh off = read_mesh(test_io::cube_off());
  ReadReport report;
  Mesh mesh = read_mesh(cube_stl_ascii(), {}, &report);
  test_io::expect_same_shape(off, mesh);
  EXPECT_EQ(mesh.V.rows(), 8);
  EXPECT_EQ(report.variant, "ascii");
  mesh = read_mesh(cube_stl_binary("binary cube"), {}, &report);
  test_io::expect_same_shape(off, mesh);
  EXPECT_EQ(mesh.V.rows(), 8);
  EXPECT_EQ(report.variant, "binary");
  EXPECT_EQ(report.faces_read, 12u);
}

TEST(ReadStl, AsciiCoordinatesAreRoundedOnceToSinglePrecisionAndWelded) {
  // Rounded through double, the first corner would be one unit in the last place off (see
  // ReadOff.TextCoordinatesAreRoundedOnceToSinglePrecision); the third equals the first.
  ReadReport report;
  const Mesh mesh = read_mesh(
      "solid t\nfacet normal 0 0 0\nouter loop\nvertex -0.182252399623394 0 0\n"
      "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\n"
      "vertex 1 0 0\nvertex 1 0 0\nvertex -0.182252399623394 0 -0\nendloop\nendfacet\n"
      "endsolid t\n",
      {}, &report);
  ASSERT_EQ(mesh.V.rows(), 3);
  EXPECT_EQ(mesh.V(0, 0), double(std::strtof("-0.182252399623394", nullptr)));
  EXPECT_EQ(mesh.F.rows(), 1);
  EXPECT_EQ(report.faces_read, 2u);
  EXPECT_EQ(report.faces_skipped, 1u);  // its corners welded into two vertices
}

TEST(ReadStl, ABinaryStlWhoseHeaderSaysSolidIsStillBinary) {
  ReadReport report;
  const Mesh mesh = read_mesh(cube_stl_binary("solid cube exported by a CAD tool"), {}, &report);
  EXPECT_EQ(report.format, MeshFormat::Stl);
  EXPECT_EQ(report.variant, "binary");
  EXPECT_EQ(mesh.F.rows(), 12);
}

TEST(ReadStl, ASolidNamedOuterIsNotATriangle) {
  // OpenMesh's ASCII reader starts a triangle at any line containing "outer".
  const Mesh mesh = read_mesh(cube_stl_ascii("outer_shell"));
  test_io::expect_same_shape(read_mesh(test_io::cube_off()), mesh);
}

TEST(ReadStl, MalformedAsciiIsAnInputErrorNamingTheLine) {
  std::string bad = cube_stl_ascii();
  bad.replace(bad.find("vertex 1 0 0"), 12, "vertex 1 0 x");
  EXPECT_NE(error_of(bad).find("STL: line"), std::string::npos);
  bad = cube_stl_ascii();
  bad.replace(bad.find("vertex 1 0 0"), 12, "vertex 1 nan");
  EXPECT_NE(error_of(bad).find("STL: line"), std::string::npos);
  bad = cube_stl_ascii();
  bad.replace(bad.find("endloop"), 7, "endlop ");
  EXPECT_NE(error_of(bad).find("line 7"), std::string::npos) << error_of(bad);
  EXPECT_NE(error_of("solid x\nendsolid x\n").find("no faces"), std::string::npos);
}

TEST(ReadStl, NonFiniteBinaryCoordinatesNameTheByteOffset) {
  std::string stl = cube_stl_binary("x");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&stl[84 + 12 + 4], &nan, 4);
  EXPECT_NE(error_of(stl).find("STL: byte offset 100"), std::string::npos) << error_of(stl);
}

TEST(ReadStl, EveryTruncationIsAnInputError) {
  // ASCII: anything cut before the final "endsolid" (a name after it is optional).
  const std::string ascii = cube_stl_ascii();
  for (std::size_t n = 0; n < ascii.rfind("endsolid") + 8; ++n) {
    if (n == ascii.rfind("endsolid") + 8) continue;
    EXPECT_THROW(read_mesh(ascii.substr(0, n)), InputError) << "prefix " << n;
  }
  // Binary: the size no longer matches the triangle count, so it is not binary STL at all.
  const std::string binary = cube_stl_binary("solid trap");
  for (std::size_t n = 0; n < binary.size(); ++n) {
    EXPECT_THROW(read_mesh(binary.substr(0, n)), InputError) << "prefix " << n;
  }
}

TEST(ReadStl, RandomCorruptionGivesTypedErrorsOnly) {
  test_io::expect_only_typed_errors(cube_stl_ascii(), 11, 400);
  test_io::expect_only_typed_errors(cube_stl_binary("solid x"), 12, 400);
}

TEST(ReadStl, TriangleCountOverTheLimitFailsBeforeReading) {
  ReadOptions options;
  options.limits.max_triangles = 11;
  EXPECT_THROW(read_mesh(cube_stl_binary("x"), options), LimitError);
  EXPECT_THROW(read_mesh(cube_stl_ascii(), options), LimitError);
}

}  // namespace
}  // namespace arg
