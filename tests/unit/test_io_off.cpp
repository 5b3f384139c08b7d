// Tests of reading OFF (our parser): plain, COFF, binary OFF, comments, colours and bad input.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <sstream>

#include "common/errors.hpp"
#include "input_error.hpp"
#include "io/read_mesh.hpp"
#include "test_io_support.hpp"

namespace arg {
namespace {

using test_io::Bytes;
using test_io::cube_off;

Mesh read(const std::string& bytes, ReadReport* report = nullptr) {
  return read_mesh(bytes, {}, report);
}

std::string error_of(const std::string& bytes) {
  return input_error_of([&] { read(bytes); });
}

TEST(ReadOff, TheCubeIsTwelveTrianglesOfAreaSixAndVolumeOne) {
  ReadReport report;
  const Mesh mesh = read(cube_off(), &report);
  EXPECT_EQ(mesh.V.rows(), 8);
  EXPECT_EQ(mesh.F.rows(), 12);
  EXPECT_NEAR(test_io::mesh_area(mesh), 6.0, 1e-12);
  EXPECT_NEAR(test_io::mesh_volume(mesh), 1.0, 1e-12);
  EXPECT_FALSE(mesh.has_colour());
  EXPECT_EQ(report.format, MeshFormat::Off);
  EXPECT_EQ(report.vertices_read, 8u);
  EXPECT_EQ(report.faces_read, 6u);
  EXPECT_EQ(report.polygons_triangulated, 6u);
  EXPECT_EQ(report.triangles, 12u);
  EXPECT_EQ(report.colour_source, "none");
}

TEST(ReadOff, CommentsBlankLinesAndCountsOnTheKeywordLineAreAccepted) {
  std::string text = cube_off();
  text.replace(0, std::string("OFF\n8 6 12\n").size(),
               "# a cube\n\nOFF 8 6 12 # counts here\n# vertices:\n");
  text += "# end\n";
  test_io::expect_same_shape(read(cube_off()), read(text));
}

TEST(ReadOff, NonManifoldFacesAreKept) {
  // Three triangles on one edge: OpenMesh's own PolyMesh would drop the third.
  const Mesh mesh =
      read("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  EXPECT_EQ(mesh.F.rows(), 3);
}

TEST(ReadOff, CoffVertexColoursGiveEachTriangleTheMeanOfItsCorners) {
  std::ostringstream s;
  s << "COFF\n8 6 0\n";
  int i = 0;
  for (const auto& v : test_io::cube_vertices()) {
    s << v[0] << ' ' << v[1] << ' ' << v[2] << (i++ < 4 ? " 255 0 0 255\n" : " 0 0 255 255\n");
  }
  for (const auto& q : test_io::cube_quads())
    s << "4 " << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << '\n';
  ReadReport report;
  const Mesh mesh = read(s.str(), &report);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_EQ(report.colour_source, "vertex");
  EXPECT_EQ(report.variant, "COFF");
  test_io::expect_same_shape(read(cube_off()), mesh);
  for (Eigen::Index t = 0; t < mesh.F.rows(); ++t) {
    // Bottom (z = 0) triangles are red, top ones blue, side ones in between.
    const double z =
        (mesh.V(mesh.F(t, 0), 2) + mesh.V(mesh.F(t, 1), 2) + mesh.V(mesh.F(t, 2), 2)) / 3;
    EXPECT_NEAR(mesh.C(t, 0), 1 - z, 1e-6);
    EXPECT_NEAR(mesh.C(t, 1), 0, 1e-6);
    EXPECT_NEAR(mesh.C(t, 2), z, 1e-6);
  }
}

TEST(ReadOff, FloatColoursAndFaceColours) {
  const std::string coff =
      "COFF\n3 1 0\n0 0 0 1.0 0.5 0.0 1.0\n1 0 0 1.0 0.5 0.0 1.0\n0 1 0 1.0 0.5 0.0 1.0\n3 0 1 2\n";
  Mesh mesh = read(coff);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_NEAR(mesh.C(0, 1), 0.5, 1e-6);
  // Geomview allows a face colour after the indices even in plain OFF.
  ReadReport report;
  mesh = read("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 0 255 0\n", &report);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_EQ(report.colour_source, "face");
  EXPECT_NEAR(mesh.C(0, 1), 1.0, 1e-6);
  EXPECT_NEAR(mesh.C(0, 0), 0.0, 1e-6);
}

TEST(ReadOff, AFaceColourOnALaterFaceOnlyIsAColourNotAFace) {
  // OpenMesh's reader, told of no colours by the header, read "255 0 0" as the next face. The
  // mesh has no colour: not every face has one.
  ReadReport report;
  const Mesh mesh =
      read("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3 255 0 0\n", &report);
  EXPECT_EQ(mesh.F.rows(), 2);
  EXPECT_EQ(report.faces_read, 2u);
  EXPECT_FALSE(mesh.has_colour());
}

TEST(ReadOff, NumbersAfterAPlainOffVertexAreNoColour) {
  // Vertex colours need the C of COFF (Geomview); a plain OFF writer's extra columns are not.
  ReadReport report;
  const Mesh mesh = read("OFF\n3 1 0\n0 0 0 9 9 9\n1 0 0 9 9 9\n0 1 0 9 9 9\n3 0 1 2\n", &report);
  EXPECT_FALSE(mesh.has_colour());
  EXPECT_EQ(report.colour_source, "none");
}

TEST(ReadOff, TextCoordinatesAreRoundedOnceToSinglePrecision) {
  // This decimal rounds to a double exactly halfway between two floats, which then goes to the
  // wrong one: the float must come from the decimal directly (strtof's, as OpenMesh stored it).
  const Mesh mesh = read("OFF\n3 1 0\n-0.182252399623394 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(mesh.V(0, 0), double(std::strtof("-0.182252399623394", nullptr)));
  EXPECT_NE(mesh.V(0, 0), double(float(-0.182252399623394)));
  // Too small for a float is zero, as strtof makes it; too large is an error.
  EXPECT_EQ(read("OFF\n3 1 0\n1e-50 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").V(0, 0), 0.0);
  EXPECT_NE(error_of("OFF\n3 1 0\n1e39 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "(no InputError)");
}

std::string binary_cube_off(bool big_endian) {
  Bytes b;
  b.text("OFF BINARY\n");
  auto i32 = [&](int v) { big_endian ? b.i32be(v) : b.i32le(v); };
  auto f32 = [&](double v) { big_endian ? b.f32be(float(v)) : b.f32le(float(v)); };
  i32(8);
  i32(6);
  i32(0);
  for (const auto& v : test_io::cube_vertices()) {
    for (double c : v) f32(c);
  }
  for (const auto& q : test_io::cube_quads()) {
    i32(4);
    for (int k : q) i32(k);
    if (big_endian) i32(0);  // Geomview: colour component count
  }
  return b.str();
}

TEST(ReadOff, BinaryOffInBothByteOrders) {
  ReadReport report;
  test_io::expect_same_shape(read(cube_off()), read(binary_cube_off(true), &report));
  EXPECT_EQ(report.variant, "OFF BINARY (big endian)");
  test_io::expect_same_shape(read(cube_off()), read(binary_cube_off(false), &report));
  EXPECT_EQ(report.variant, "OFF BINARY (little endian)");
}

TEST(ReadOff, EveryTruncationIsAnInputError) {
  for (const std::string& full : {cube_off(), binary_cube_off(true)}) {
    for (std::size_t n = 0; n + 1 < full.size(); ++n) {
      EXPECT_THROW(read(full.substr(0, n)), InputError) << "prefix of " << n << " bytes";
    }
  }
}

TEST(ReadOff, MalformedInputIsAnInputErrorNamingTheLine) {
  EXPECT_NE(error_of("OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n").find("OFF: line 4"),
            std::string::npos);
  EXPECT_NE(error_of("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n").find("line 6"),
            std::string::npos);
  EXPECT_NE(error_of("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n").find("vertex"),
            std::string::npos);
  EXPECT_NE(error_of("OFF\n3 1 0\nnan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").find("OFF: line 3"),
            std::string::npos);
  EXPECT_NE(
      error_of("COFF\n3 1 0\n0 0 inf 1 0 0\n1 0 0 1 0 0\n0 1 0 1 0 0\n3 0 1 2\n").find("finite"),
      std::string::npos);
  EXPECT_NE(error_of("OFF\nthree 1 0\n").find("counts"), std::string::npos);
  EXPECT_NE(error_of("4OFF\n1 0 0\n0 0 0 1\n").find("not supported"), std::string::npos);
  EXPECT_NE(error_of("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n").find("no faces"), std::string::npos);
}

TEST(ReadOff, HugeDeclaredCountsFailFast) {
  const auto start = std::chrono::steady_clock::now();
  const std::string message =
      error_of("OFF\n1000000000 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_NE(message.find("declares 1000000000 vertices"), std::string::npos) << message;
  EXPECT_NE(error_of("OFF\n4294967295 1 0\n0 0 0\n").find("declares"), std::string::npos);
  Bytes binary;
  binary.text("OFF BINARY\n").i32be(1000000000).i32be(1000000000).i32be(0).f32be(0);
  EXPECT_NE(error_of(binary.str()).find("declares"), std::string::npos);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(ReadOff, CountsOverTheLimitsAreALimitError) {
  ReadOptions options;
  options.limits.max_vertices = 7;
  EXPECT_THROW(read_mesh(cube_off(), options), LimitError);
  options.limits.max_vertices = 8;
  options.limits.max_triangles = 11;
  EXPECT_THROW(read_mesh(cube_off(), options), LimitError);
  options.limits.max_triangles = 12;
  EXPECT_EQ(read_mesh(cube_off(), options).F.rows(), 12);
}

TEST(ReadOff, RandomCorruptionGivesTypedErrorsOnly) {
  test_io::expect_only_typed_errors(cube_off(), 1, 400);
  test_io::expect_only_typed_errors(binary_cube_off(true), 2, 400);
  test_io::expect_only_typed_errors(
      "COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 1 0\n0 1 0 0 0 1\n3 0 1 2 255 0 0\n", 3, 400);
}

TEST(ReadOff, TheStopCallbackInterrupts) {
  std::ostringstream s;
  s << "OFF\n20000 1 0\n";
  for (int i = 0; i < 20000; ++i) s << i << " 0 0\n";
  s << "3 0 1 2\n";
  ReadOptions options;
  options.stop = [] { return true; };
  EXPECT_THROW(read_mesh(s.str(), options), Interrupted);
}

}  // namespace
}  // namespace arg
