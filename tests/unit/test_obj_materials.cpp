// Tests of an OBJ's material textures: each face maps its usemtl's image, for display only.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "io/read_mesh.hpp"
#include "test_io_support.hpp"

namespace arg {
namespace {

// A triangle before any usemtl, then a quad of material a, a quad of b and a triangle of c.
const char* const kObj =
    "mtllib two.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nv 3 0 0\nv 3 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "f 5/1 7/2 8/3\n"
    "usemtl a\n"
    "f 1/1 2/2 3/3 4/4\n"
    "usemtl b  # a comment\n"
    "f 2/1 5/2 6/3 3/4\n"
    "usemtl c\n"
    "f 5/1 8/3 6/4\n";

std::string solid_png(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  return test_io::encode_image("png", 2, 2, [=](int, int) {
    return std::array<std::uint8_t, 3>{r, g, b};
  });
}

// The map of each triangle, by the face it came from: the first triangle is the one before
// usemtl, the next two material a's quad, then b's two, then c's one.
std::vector<int> maps_by_face(const Mesh& mesh, const MeshTexture& texture) {
  EXPECT_EQ(mesh.F.rows(), 6);
  return texture.triangle_map;
}

bool has_warning(const ReadReport& report, const std::string& part) {
  return std::any_of(report.warnings.begin(), report.warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

// Whether `obj`, read with material a's texture a red image, maps no texture in its display.
bool maps_nothing(const std::string& obj, ReadReport& report) {
  const std::string red = solid_png(255, 0, 0);
  ReadOptions options;
  options.material_textures = {{"a", red}};
  MeshTexture texture;
  read_mesh(obj, options, &report, &texture);
  return texture.empty();
}

void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.V.rows(), b.V.rows());
  ASSERT_EQ(a.F.rows(), b.F.rows());
  EXPECT_TRUE(a.V == b.V);
  EXPECT_TRUE(a.F == b.F);
  ASSERT_EQ(a.C.rows(), b.C.rows());
  EXPECT_TRUE(a.C == b.C);
}

TEST(ObjMaterials, EachMaterialMapsItsImage) {
  const std::string red = solid_png(255, 0, 0), blue = solid_png(0, 0, 255);
  ReadOptions options;
  options.material_textures = {{"a", red}, {"b", blue}};
  ReadReport report;
  MeshTexture texture;
  const Mesh mesh = read_mesh(kObj, options, &report, &texture);
  ASSERT_FALSE(texture.empty());
  EXPECT_EQ(texture.images.size(), 2u);
  ASSERT_EQ(texture.maps.size(), 2u);
  EXPECT_EQ(texture.maps[0].image, 0);
  EXPECT_EQ(texture.maps[1].image, 1);
  EXPECT_EQ(texture.images[0].encoded, red);
  EXPECT_EQ(texture.images[1].image.rgb[2], 255);
  EXPECT_EQ(maps_by_face(mesh, texture), (std::vector<int>{-1, 0, 0, 1, 1, -1}));
  // The triangle before any usemtl keeps no coordinates; a's keep theirs.
  EXPECT_TRUE(std::isnan(texture.uv[0]));
  EXPECT_FALSE(std::isnan(texture.uv[6]));
  // c has no image: said by name; the face before usemtl is no material's, so no warning.
  EXPECT_TRUE(has_warning(report, "material 'c' has no texture image")) << report.warnings.size();
  EXPECT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.colour_source, "none");  // colour comes from ReadOptions::texture alone
}

TEST(ObjMaterials, MaterialsSharingAnImageShareIt) {
  const std::string red = solid_png(255, 0, 0);
  ReadOptions options;
  options.material_textures = {{"a", red}, {"b", red}, {"c", red}};
  MeshTexture texture;
  const Mesh mesh = read_mesh(kObj, options, nullptr, &texture);
  EXPECT_EQ(texture.images.size(), 1u);
  EXPECT_EQ(texture.maps.size(), 3u);
  EXPECT_EQ(maps_by_face(mesh, texture), (std::vector<int>{-1, 0, 0, 1, 1, 2}));
}

TEST(ObjMaterials, AnImageThatDoesNotDecodeMapsNothing) {
  const std::string green = solid_png(0, 255, 0);
  ReadOptions options;
  options.material_textures = {{"a", "not an image"}, {"b", green}};
  ReadReport report;
  MeshTexture texture;
  const Mesh mesh = read_mesh(kObj, options, &report, &texture);
  EXPECT_EQ(texture.images.size(), 1u);
  EXPECT_EQ(maps_by_face(mesh, texture), (std::vector<int>{-1, -1, -1, 0, 0, -1}));
  EXPECT_TRUE(has_warning(report, "the texture of material 'a' is not shown"));
  EXPECT_TRUE(has_warning(report, "material 'c'"));
}

TEST(ObjMaterials, TheMeshIsTheSameWithOrWithoutThem) {
  const std::string red = solid_png(255, 0, 0), blue = solid_png(0, 0, 255);
  const std::string colour = solid_png(10, 200, 30);
  for (bool coloured : {false, true}) {
    ReadOptions plain;
    if (coloured) plain.texture = colour;
    ReadOptions with = plain;
    with.material_textures = {{"a", red}, {"b", blue}};
    MeshTexture texture;
    const Mesh expected = read_mesh(kObj, plain);
    expect_same_mesh(expected, read_mesh(kObj, with, nullptr, &texture));
    expect_same_mesh(expected, read_mesh(kObj, with));
    EXPECT_EQ(texture.maps.size(), 2u);
    EXPECT_EQ(expected.has_colour(), coloured);
  }
}

TEST(ObjMaterials, WithoutMaterialTexturesOneTextureMapsAll) {
  const std::string colour = solid_png(10, 200, 30);
  ReadOptions options;
  options.texture = colour;
  MeshTexture texture;
  const Mesh mesh = read_mesh(kObj, options, nullptr, &texture);
  EXPECT_EQ(texture.maps.size(), 1u);
  EXPECT_EQ(maps_by_face(mesh, texture), (std::vector<int>(6, 0)));
}

TEST(ObjMaterials, NoCoordinatesNoMaterialTextures) {
  ReadReport report;
  EXPECT_TRUE(maps_nothing("v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl a\nf 1 2 3\n", report));
  EXPECT_TRUE(has_warning(report, "no texture coordinates"));
}

// OpenMesh drops a face that repeats a corner: the faces no longer follow the f lines, so no
// face is trusted to have its line's material.
TEST(ObjMaterials, FacesOpenMeshDropsTurnThemOff) {
  ReadReport report;
  EXPECT_TRUE(maps_nothing(std::string(kObj) + "f 1/1 2/2 1/1\n", report));
  EXPECT_TRUE(has_warning(report, "OpenMesh added 4 faces for 5 face lines"));
}

TEST(ObjMaterials, MoreImagesThanTheCapMapTheFirstOnly) {
  std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n";
  ReadOptions options;
  std::vector<std::string> images;
  const std::size_t n = kMaxDisplayImages + 2;
  for (std::size_t i = 0; i < n; ++i) images.push_back(solid_png(std::uint8_t(i), 0, 0));
  for (std::size_t i = 0; i < n; ++i) {
    obj += "usemtl m" + std::to_string(i) + "\nf 1/1 2/2 3/3\n";
    options.material_textures.push_back({"m" + std::to_string(i), images[i]});
  }
  ReadReport report;
  MeshTexture texture;
  read_mesh(obj, options, &report, &texture);
  EXPECT_EQ(texture.images.size(), kMaxDisplayImages);
  ASSERT_EQ(texture.triangle_map.size(), n);
  EXPECT_EQ(texture.triangle_map[kMaxDisplayImages - 1], int(kMaxDisplayImages) - 1);
  EXPECT_EQ(texture.triangle_map[kMaxDisplayImages], -1);
  EXPECT_TRUE(has_warning(report, "material 'm" + std::to_string(kMaxDisplayImages) + "'"));
}

}  // namespace
}  // namespace arg
