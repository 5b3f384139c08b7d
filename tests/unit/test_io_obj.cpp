// Tests of reading OBJ through OpenMesh: shape, colours, textures, polygons and bad input.
#include <gtest/gtest.h>

#include <chrono>
#include <sstream>

#include "common/errors.hpp"
#include "input_error.hpp"
#include "io/read_mesh.hpp"
#include "test_io_support.hpp"

namespace arg {
namespace {

std::string cube_obj(bool with_uv = false) {
  std::ostringstream s;
  s << "# cube\nmtllib cube.mtl\no cube\n";
  for (const auto& v : test_io::cube_vertices())
    s << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  if (with_uv) s << "vt 0.25 0.1\nvt 0.75 0.1\nvt 0.75 0.9\nvt 0.25 0.9\n";
  s << "usemtl skin\n";
  for (const auto& q : test_io::cube_quads()) {
    s << 'f';
    for (int k = 0; k < 4; ++k) {
      s << ' ' << q[std::size_t(k)] + 1;
      if (with_uv) s << '/' << (k + 1);
    }
    s << '\n';
  }
  return s.str();
}

std::string error_of(const std::string& bytes) {
  return input_error_of([&] { read_mesh(bytes); });
}

TEST(ReadObj, TheCubeReadsAsTheOffCube) {
  ReadReport report;
  const Mesh mesh = read_mesh(cube_obj(), {}, &report);
  test_io::expect_same_shape(read_mesh(test_io::cube_off()), mesh);
  EXPECT_EQ(report.format, MeshFormat::Obj);
  EXPECT_EQ(report.faces_read, 6u);
  EXPECT_EQ(report.polygons_triangulated, 6u);
  EXPECT_EQ(report.colour_source, "none");
}

TEST(ReadObj, CornerFormsAndNegativeIndices) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1\nf -3//1 -2//1 -1//1\nf 1/1 2/2 3/3\n";
  const Mesh mesh = read_mesh(obj);
  EXPECT_EQ(mesh.F.rows(), 3);
  EXPECT_NEAR(test_io::mesh_area(mesh), 1.5, 1e-12);
}

TEST(ReadObj, VertexColoursWhenEveryVertexHasOne) {
  std::string obj = "v 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n";
  ReadReport report;
  Mesh mesh = read_mesh(obj, {}, &report);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_EQ(report.colour_source, "vertex");
  EXPECT_NEAR(mesh.C(0, 0), 2.0 / 3, 1e-6);
  EXPECT_NEAR(mesh.C(0, 2), 1.0 / 3, 1e-6);
  // With one vertex uncoloured, OpenMesh's list of colours would be shifted: none are used.
  mesh = read_mesh("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n", {}, &report);
  EXPECT_FALSE(mesh.has_colour());
}

// A 4x4 texture: the top half red, the bottom half blue.
std::string red_over_blue_png() {
  return test_io::encode_image("png", 4, 4, [](int, int y) {
    return y < 2 ? std::array<std::uint8_t, 3>{255, 0, 0} : std::array<std::uint8_t, 3>{0, 0, 255};
  });
}

TEST(ReadObj, TextureColoursFollowTheObjConventionThatVZeroIsAtTheBottom) {
  const std::string png = red_over_blue_png();
  ASSERT_FALSE(png.empty());
  const std::string top =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.3 0.8\nvt 0.6 0.8\nvt 0.4 0.7\nf 1/1 2/2 3/3\n";
  const std::string bottom =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.3 0.2\nvt 0.6 0.2\nvt 0.4 0.3\nf 1/1 2/2 3/3\n";
  ReadOptions options;
  options.texture = png;
  ReadReport report;
  Mesh mesh = read_mesh(top, options, &report);
  ASSERT_TRUE(mesh.has_colour());
  EXPECT_EQ(report.colour_source, "texture");
  EXPECT_NEAR(mesh.C(0, 0), 1.0, 1e-6);
  EXPECT_NEAR(mesh.C(0, 2), 0.0, 1e-6);
  mesh = read_mesh(bottom, options);
  EXPECT_NEAR(mesh.C(0, 0), 0.0, 1e-6);
  EXPECT_NEAR(mesh.C(0, 2), 1.0, 1e-6);
}

// A quad in two triangles whose texture coordinates differ per corner at the shared vertices
// (a seam): read_mesh's MeshTexture keeps them per corner, the mesh itself unchanged.
TEST(ReadObj, TextureCoordinatesAreKeptPerCornerForDisplay) {
  const std::string png = red_over_blue_png();
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
      "f 1/1 2/2 3/3\nf 1/5 3/3 4/4\n";
  ReadOptions options;
  options.texture = png;
  MeshTexture texture;
  const Mesh mesh = read_mesh(obj, options, nullptr, &texture);
  ASSERT_FALSE(texture.empty());
  ASSERT_EQ(texture.images.size(), 1u);
  ASSERT_EQ(texture.maps.size(), 1u);
  EXPECT_EQ(texture.images[0].encoded, png);
  EXPECT_EQ(texture.images[0].image.width, 4);
  EXPECT_TRUE(texture.maps[0].sampler.v_origin_bottom);
  EXPECT_EQ(texture.maps[0].factor, (std::array<float, 3>{1, 1, 1}));
  const std::vector<float> expected = {0, 0, 1, 0, 1, 1, 0.5f, 0.5f, 1, 1, 0, 1};
  EXPECT_EQ(texture.uv, expected);
  EXPECT_EQ(texture.triangle_map, (std::vector<int>{0, 0}));
  // The same mesh and colours as a read that does not ask for them.
  const Mesh plain = read_mesh(obj, options);
  EXPECT_EQ(mesh.V, plain.V);
  EXPECT_EQ(mesh.F, plain.F);
  EXPECT_EQ(mesh.C, plain.C);
  // Without the texture, or without coordinates, there is nothing to map.
  read_mesh(obj, {}, nullptr, &texture);
  EXPECT_TRUE(texture.empty());
  read_mesh(cube_obj(), options, nullptr, &texture);
  EXPECT_TRUE(texture.empty());
}

TEST(ReadObj, ATextureCoordinateIndexOutOfRangeIsRefused) {
  ReadOptions options;
  const std::string png = red_over_blue_png();
  options.texture = png;
  MeshTexture texture;
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nf 1/1 2/2 3/3\n";
  try {
    read_mesh(obj, options, nullptr, &texture);
    FAIL() << "read an OBJ whose face names texture coordinate 3 of 2";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 6: a face refers to texture coordinate 3 but the "
                                         "file has 2"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(
      read_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/-2 3/1\n", options, nullptr, &texture),
      InputError);
}

TEST(ReadObj, TextureWithoutTextureCoordinatesIsIgnoredWithAWarning) {
  ReadOptions options;
  const std::string png = red_over_blue_png();
  options.texture = png;
  ReadReport report;
  const Mesh mesh = read_mesh(cube_obj(), options, &report);
  EXPECT_FALSE(mesh.has_colour());
  ASSERT_EQ(report.warnings.size(), 1u);
  // And a bad texture is an error only when it is used.
  options.texture = "not an image";
  EXPECT_THROW(read_mesh(cube_obj(true), options), InputError);
}

TEST(ReadObj, MaterialLinesNeverReachTheFileSystem) {
  // OpenMesh would open the mtllib file by name (here a device that never ends).
  const Mesh mesh = read_mesh("mtllib /dev/zero\nusemtl x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(mesh.F.rows(), 1);
}

TEST(ReadObj, ConcavePolygonsAreTriangulatedWithoutOverlap) {
  // An L of three unit squares, as one hexagon; a fan from its first corner would cover 4.
  const std::string obj = "v 0 2 0\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nf 1 2 3 4 5 6\n";
  ReadReport report;
  const Mesh mesh = read_mesh(obj, {}, &report);
  EXPECT_EQ(mesh.F.rows(), 4);
  EXPECT_NEAR(test_io::mesh_area(mesh), 3.0, 1e-12);
  EXPECT_EQ(report.polygons_triangulated, 1u);
}

TEST(ReadObj, MalformedLinesAreInputErrorsNamingTheLine) {
  EXPECT_NE(error_of("v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n").find("OBJ: line 2"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 x\nv 0 1 0\nf 1 2 3\n").find("line 2"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n").find("finite"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 1e39\nv 0 1 0\nf 1 2 3\n").find("line 2"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n").find("line 4"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n").find("line 4"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nf -3 1 2\nv 0 1 0\n").find("line 3"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/x\n").find("line 4"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5\nf 1 2 3\n").find("line 4"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2 2/1 3/1\nvt 0 0\n").find("texture"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nf 1 2\n").find("line 3"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\n").find("no faces"), std::string::npos);
}

TEST(ReadObj, EveryTruncationIsAnInputErrorOrAValidPrefix) {
  const std::string full = cube_obj(true);
  for (std::size_t n = 0; n < full.size(); ++n) {
    try {
      read_mesh(full.substr(0, n));
    } catch (const InputError&) {
    }
  }
}

TEST(ReadObj, RandomCorruptionGivesTypedErrorsOnly) {
  ReadOptions options;
  const std::string png = red_over_blue_png();
  options.texture = png;
  test_io::expect_only_typed_errors(cube_obj(true), 4, 400, options);
  test_io::expect_only_typed_errors(cube_obj(false), 5, 400);
}

TEST(ReadObj, LimitsApply) {
  ReadOptions options;
  options.limits.max_vertices = 7;
  EXPECT_THROW(read_mesh(cube_obj(), options), LimitError);
  options.limits.max_vertices = 8;
  options.limits.max_triangles = 11;
  EXPECT_THROW(read_mesh(cube_obj(), options), LimitError);
}

}  // namespace
}  // namespace arg
